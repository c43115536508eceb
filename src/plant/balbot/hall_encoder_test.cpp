#include "hall_encoder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "balbot_test_bench.hpp"

namespace duet::plant {
namespace {

using testing::BalbotBench;

struct Captures {
  std::vector<double> counts;
  std::vector<double> b_levels;
};

// The wheels turned at `rev_s` (forward when positive) for `seconds`; each hall capture's count and B level.
std::pair<Captures, Captures> captures_at(double rev_s, double seconds) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.rig = BalbotRig::wheels_driven;
  scenario.driven_wheel_rev_s = rev_s;
  BalbotBench bench{scenario};
  Captures left;
  Captures right;
  bench.on_interrupt = [&](std::string_view interrupt) {
    if (interrupt == "TIM2") {
      left.counts.push_back(bench.get("capture:TIM2/1", 2)[0]);
      EXPECT_EQ(bench.get("capture:TIM2/1", 2)[1], 1);  // a rising edge
      left.b_levels.push_back(bench.get("gpio:PH6"));
    }
    if (interrupt == "TIM4") {
      right.counts.push_back(bench.get("capture:TIM4/4", 2)[0]);
      right.b_levels.push_back(bench.get("gpio:PG3"));
    }
  };
  bench.record = false;
  bench.run_until(seconds);
  return {left, right};
}

void expect_counts(const Captures& captures, double expected, std::size_t at_least) {
  ASSERT_GE(captures.counts.size(), at_least);
  for (std::size_t i = 1; i < captures.counts.size(); ++i) {  // the first counts from time 0
    EXPECT_NEAR(captures.counts[i], expected, 1.0) << "capture " << i;
  }
}

TEST(BalbotHall, CaptureCountsAreTheMicrosecondsBetweenEdges) {
  const auto [left, right] = captures_at(2.0, 0.5);
  const double period_us = 1e6 / (450 * 2.0);  // 1111.1
  expect_counts(left, period_us, 440);
  expect_counts(right, period_us, 440);
  // Forward: the left motor turns clockwise (B low at A's rising edge), the right one counter-clockwise (B high).
  for (const double b : left.b_levels) EXPECT_EQ(b, 0);
  for (const double b : right.b_levels) EXPECT_EQ(b, 1);
}

TEST(BalbotHall, BackwardsTheDirectionsSwap) {
  const auto [left, right] = captures_at(-1.5, 0.5);
  expect_counts(left, 1e6 / (450 * 1.5), 330);
  expect_counts(right, 1e6 / (450 * 1.5), 330);
  for (const double b : left.b_levels) EXPECT_EQ(b, 1);
  for (const double b : right.b_levels) EXPECT_EQ(b, 0);
}

TEST(BalbotHall, AtTheMotorsTopSpeedThePeriodIsTheThesis501us) {
  const auto [left, right] = captures_at(4.43, 0.2);
  expect_counts(left, 501.6, 170);  // the thesis measured 501.57 us
  expect_counts(right, 501.6, 170);
}

TEST(BalbotHall, SlowCountsWrapAt16Bits) {
  const auto [left, right] = captures_at(0.02, 0.5);  // 111111 us between edges
  expect_counts(left, 111111 - 65536, 4);
}

TEST(BalbotHall, ATurnBackInsideOneStepStillGivesEveryEdge) {
  // Over one 1 ms segment the wheel turns forward by 1.6 cycles of A and back to where it started.
  balbot::HallEncoder encoder{+1, 450, 0.0};
  const double cycle = 2 * std::numbers::pi / 450;
  encoder.start(0.01 * cycle);  // 0.01 cycles: A high
  // angle(tau) = cycle (0.01 + 6.4 tau (1 - tau)): up to 1.61 cycles at tau = 0.5, back to 0.01 at tau = 1.
  const balbot::Cubic angle{0.01 * cycle, 6.4 * cycle, -6.4 * cycle, 0};
  const balbot::TurningPoints turns = balbot::turning_points(angle);
  ASSERT_EQ(turns.count, 3U);
  EXPECT_DOUBLE_EQ(turns.bounds[1], 0.5);
  encoder.plan(angle, turns, 0, 1'000'000, 0.0);
  // Up through 0.5 (A falls), 1 (rises), 1.5 (falls); back down through 1.5 (rises), 1 (falls), 0.5 (rises).
  ASSERT_EQ(encoder.planned().size(), 6U);
  std::vector<double> rising_times;
  while (const auto event = encoder.next_event()) {
    rising_times.push_back(static_cast<double>(event->time) * 1e-9);
    EXPECT_TRUE(encoder.take_next().rising_edge);
  }
  ASSERT_EQ(rising_times.size(), 3U);
  // Where the phase reaches 1 cycle on the way up, 1.5 and 0.5 on the way back (each 1e-4 cycles of hysteresis on).
  const auto tau_at = [](double cycles, bool back) {
    const double root = std::sqrt(1 - 4 * (cycles - 0.01) / 6.4);
    return back ? (1 + root) / 2 : (1 - root) / 2;
  };
  EXPECT_NEAR(rising_times[0], tau_at(1.0001, false) * 1e-3, 1e-9);
  EXPECT_NEAR(rising_times[1], tau_at(1.4999, true) * 1e-3, 1e-9);
  EXPECT_NEAR(rising_times[2], tau_at(0.4999, true) * 1e-3, 1e-9);
  EXPECT_TRUE(encoder.a_high());
}

TEST(BalbotHall, AFullPlanIsContinued) {
  // 40 half-cycles in one segment: more than one plan holds.
  balbot::HallEncoder encoder{+1, 450, 0.0};
  const double cycle = 2 * std::numbers::pi / 450;
  encoder.start(0.25 * cycle);
  const balbot::Cubic angle{0.25 * cycle, 20 * cycle, 0, 0};
  const balbot::TurningPoints turns = balbot::turning_points(angle);
  encoder.plan(angle, turns, 0, 1'000'000, 0.0);
  EXPECT_EQ(encoder.planned().size(), balbot::HallEncoder::most_planned);
  int rising = 0;
  while (encoder.next_event()) {
    const balbot::HallEncoder::Taken taken = encoder.take_next();
    rising += taken.rising_edge ? 1 : 0;
    if (taken.plan_again) encoder.plan(angle, turns, 0, 1'000'000, taken.tau);
  }
  EXPECT_EQ(rising, 20);
}

}  // namespace
}  // namespace duet::plant
