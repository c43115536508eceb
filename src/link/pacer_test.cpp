// The pacer against a clock the test moves: where it sleeps to, how it counts late ticks (after their wait, the
// first second apart, in stretches, in a histogram), and how fast it finds the loop between ticks could go.
#include "duet/link/pacer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <vector>

namespace duet::link {
namespace {

using namespace std::chrono_literals;

class FakeClock final : public PacingClock {
 public:
  time_point now() override { return now_; }
  void sleep_until(time_point deadline) override {
    sleeps.push_back(deadline);
    now_ = std::max(now_, deadline) + oversleep;
  }
  void pass(std::chrono::nanoseconds duration) { now_ += duration; }

  std::vector<time_point> sleeps;
  std::chrono::nanoseconds oversleep{0};  // how much later than asked a sleep ends

 private:
  time_point now_{std::chrono::hours{1}};
};

// Ticks of 1 ms from time 0 to `ticks` - 1, the loop taking `busy(tick)` of wall time before each but the first.
template <typename Busy>
void run(Pacer& pacer, FakeClock& clock, int ticks, Busy busy) {
  for (int tick = 0; tick < ticks; ++tick) {
    if (tick > 0) clock.pass(busy(tick));
    pacer.wait_until(tick * 0.001);
  }
}

TEST(Pacer, TheFirstTickFixesTheOriginAndTheOthersWaitForTheirTime) {
  FakeClock clock;
  Pacer pacer{clock};
  const PacingClock::time_point start = clock.now();
  pacer.wait_until(0.5);  // the origin: 0.5 s before now
  EXPECT_TRUE(clock.sleeps.empty());
  clock.pass(200us);
  pacer.wait_until(0.501);
  ASSERT_EQ(clock.sleeps.size(), 1U);
  EXPECT_EQ(clock.sleeps[0], start + 1ms);
  EXPECT_EQ(clock.now(), start + 1ms);
  EXPECT_EQ(pacer.late(), 0U);
  EXPECT_EQ(pacer.report().first_second.ticks, 2U);
}

TEST(Pacer, ATickIsLateWhenItGoesMoreThanTheThresholdAfterItsTime) {
  FakeClock clock;
  Pacer pacer{clock};
  pacer.wait_until(0);
  clock.pass(1900us);
  pacer.wait_until(0.001);  // 0.9 ms late: within the threshold of 1 ms
  clock.pass(1200us);
  pacer.wait_until(0.002);  // 1.1 ms late
  EXPECT_EQ(pacer.late(), 1U);
  EXPECT_EQ(pacer.worst_lateness(), 1100us);
  EXPECT_TRUE(clock.sleeps.empty());  // a late tick goes at once

  Pacer strict{clock};
  strict.set_late_threshold(100us);
  strict.wait_until(0);
  clock.pass(1200us);
  strict.wait_until(0.001);
  EXPECT_EQ(strict.late(), 1U);
}

TEST(Pacer, AWakeUpAfterTheDeadlineIsLatenessToo) {
  FakeClock clock;
  clock.oversleep = 3ms;  // a machine that gives the thread its processor 3 ms late
  Pacer pacer{clock};
  run(pacer, clock, 3, [](int) { return 100us; });
  // Tick 1 waited and woke 3 ms late; tick 2 then came 2.1 ms late without waiting.
  EXPECT_EQ(pacer.late(), 2U);
  EXPECT_EQ(pacer.worst_lateness(), 3ms);
}

TEST(Pacer, TheFirstSecondIsCountedApart) {
  FakeClock clock;
  Pacer pacer{clock};
  // The first 10 ticks take 5 ms each (start-up), then 0.5 ms: the run catches up within the first second.
  run(pacer, clock, 2001, [](int tick) { return tick <= 10 ? 5ms : 500us; });
  const PacingReport& report = pacer.report();
  EXPECT_EQ(report.first_second.ticks, 1000U);
  EXPECT_GT(report.first_second.late, 10U);
  EXPECT_EQ(report.first_second.worst, 40ms);  // tick 10: 50 ms of wall time for 10 ms of model time
  EXPECT_EQ(report.after_first_second.ticks, 1001U);
  EXPECT_EQ(report.after_first_second.late, 0U);
  EXPECT_EQ(report.after_first_second.worst, 0ns);
  EXPECT_EQ(pacer.late(), report.first_second.late);
}

// Ticks of 0.5 ms, but after the first second every `every`-th takes `stall`: how the ticks after it went.
Lateness after_stalls(int ticks, int every, std::chrono::microseconds stall) {
  FakeClock clock;
  Pacer pacer{clock};
  run(pacer, clock, ticks, [&](int tick) { return tick > 1000 && tick % every == 0 ? stall : 500us; });
  return pacer.report().after_first_second;
}

TEST(Pacer, LateTicksComeInStretchesAfterAStall) {
  // A stall of 4 ms every 100 ms leaves the loop 3 ms behind, and it catches up by 0.5 ms a tick: 3, 2.5, 2 and
  // 1.5 ms late, four ticks over 1 ms (then 1 ms is not).
  const Lateness settled = after_stalls(1551, 100, 4ms);
  EXPECT_EQ(settled.ticks, 551U);
  EXPECT_EQ(settled.late_stretches, 5U);
  EXPECT_EQ(settled.late, 5U * 4U);
  EXPECT_EQ(settled.longest_stretch, 4U);
  EXPECT_EQ(settled.worst, 3ms);
  EXPECT_DOUBLE_EQ(settled.late_fraction(), 20.0 / 551.0);
}

TEST(Pacer, TheHistogramSaysWithinWhatLatenessMostTicksWent) {
  // A stall of 7.5 ms every second: 6.5 ms late, then 6, 5.5, ... 0.5.
  const Lateness settled = after_stalls(11101, 1000, 7500us);
  ASSERT_EQ(settled.ticks, 10101U);
  EXPECT_EQ(settled.late, 10U * 11U);
  EXPECT_EQ(settled.late_stretches, 10U);
  EXPECT_EQ(settled.longest_stretch, 11U);
  const std::array<std::uint64_t, 10> expected{10101 - 130, 10, 10, 20, 60, 30, 0, 0, 0, 0};
  EXPECT_EQ(settled.histogram, expected);  // 0.1, 0.5, 1, 2, 5, 10 ms, ...
  EXPECT_EQ(settled.within(0.99), 2ms);    // 10,011 ticks within 2 ms
  EXPECT_EQ(settled.within(0.999), 10ms);
  EXPECT_EQ(Lateness{}.within(0.99), 100us);  // no ticks: nothing beyond any bound
}

TEST(Pacer, LatenessBeyondTheLastBinIsOverIt) {
  FakeClock clock;
  Pacer pacer{clock};
  run(pacer, clock, 1101, [](int tick) { return tick > 1000 ? 3ms : 1ms; });  // 2 ms further behind each tick
  const Lateness& settled = pacer.report().after_first_second;
  EXPECT_EQ(settled.histogram.back(), 50U);  // ticks 1051 to 1100: over 100 ms late
  EXPECT_FALSE(settled.within(0.99));
}

TEST(Pacer, TheLoopSpeedIsModelTimeOverTheWallTimeTheLoopTookWithoutTheWaits) {
  FakeClock clock;
  Pacer pacer{clock};
  run(pacer, clock, 2001, [](int tick) { return tick == 1500 ? 10ms : 400us; });
  const PacingReport& report = pacer.report();
  // The intervals that end at ticks 1000 to 2000: 1,000 of 0.4 ms and one of 10 ms.
  EXPECT_NEAR(report.busy_model_s, 1.001, 1e-12);
  EXPECT_EQ(report.busy_wall, 1000 * 400us + 10ms);
  EXPECT_EQ(report.longest_busy, 10ms);
  ASSERT_TRUE(report.loop_speed());
  EXPECT_NEAR(*report.loop_speed(), 1.001 / 0.410, 1e-9);
  EXPECT_FALSE(PacingReport{}.loop_speed());
}

TEST(Pacer, ALoopSlowerThanRealTimeFallsFurtherBehind) {
  FakeClock clock;
  Pacer pacer{clock};
  run(pacer, clock, 3001, [](int) { return 1250us; });
  const PacingReport& report = pacer.report();
  ASSERT_TRUE(report.loop_speed());
  EXPECT_NEAR(*report.loop_speed(), 0.8, 1e-9);
  EXPECT_EQ(report.after_first_second.late, 2001U);  // already 250 ms behind when the first second ended
  EXPECT_EQ(report.after_first_second.late_stretches, 1U);
  EXPECT_EQ(report.after_first_second.worst, 750ms);
}

}  // namespace
}  // namespace duet::link
