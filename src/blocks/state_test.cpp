#include "duet/blocks/state.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <type_traits>
#include <vector>

namespace duet::blocks {
namespace {

// Plain aggregates: generated code and XCP can lay them out, copy them and read their members.
static_assert(std::is_aggregate_v<DiscretePid<float>> && std::is_standard_layout_v<DiscretePid<float>>);
static_assert(std::is_trivially_copyable_v<DiscreteIntegrator<double>> && std::is_aggregate_v<Counter<std::int16_t>>);
static_assert(sizeof(UnitDelay<std::int8_t>) == 1 && sizeof(DiscretePid<float>) == 2 * sizeof(float));

// Several steps of a block in a constant expression: parameters and initial states can be computed at compile time.
constexpr std::int16_t count_after(int steps) {
  Counter<std::int16_t> counter{0};
  for (int step = 0; step < steps; ++step) counter.update(2);
  return counter.output();
}
static_assert(count_after(2) == 2 && count_after(3) == 0 && count_after(4) == 1);

constexpr double integrated_after_two_steps() {
  DiscreteIntegrator<double> integrator{0.0};
  integrator.update(1.0, 2.0, 0.5, -10.0, 10.0);
  integrator.update(1.0, 2.0, 0.5, -10.0, 10.0);
  return integrator.output();
}
static_assert(integrated_after_two_steps() == 2.0);

TEST(BlocksUnitDelay, OutputsThePreviousInput) {
  UnitDelay<float> delay{0.5F};
  std::vector<float> outputs;
  for (const float u : {1.0F, 2.0F, -3.0F}) {
    outputs.push_back(delay.output());
    delay.update(u);
  }
  outputs.push_back(delay.output());
  EXPECT_EQ(outputs, (std::vector<float>{0.5F, 1.0F, 2.0F, -3.0F}));

  UnitDelay<bool> flag{true};
  flag.update(false);
  EXPECT_FALSE(flag.output());
  UnitDelay<std::int16_t> word{-7};
  EXPECT_EQ(word.output(), -7);
}

TEST(BlocksDiscreteIntegrator, ForwardEulerWithTheGainTimesPeriodFirst) {
  const double gain = 0.7;
  const double period = 0.01;
  DiscreteIntegrator<double> integrator{0.0};
  double expected = 0.0;
  double other_order = 0.0;  // gain * (period * u) instead
  bool orders_differ = false;
  for (const double u : {0.13, 1.3, -0.07, 0.17, 2.9}) {
    EXPECT_EQ(integrator.output(), expected);  // y(k) = x(k): the input acts one step later
    integrator.update(u, gain, period, -1.0, 1.0);
    expected = expected + (gain * period) * u;
    other_order = other_order + gain * (period * u);
    orders_differ = orders_differ || other_order != expected;
  }
  EXPECT_EQ(integrator.output(), expected);
  EXPECT_TRUE(orders_differ);  // so the comparison above pins the order
}

TEST(BlocksDiscreteIntegrator, StateSaturatesAtTheLimits) {
  DiscreteIntegrator<float> integrator{0.0F};
  std::vector<float> outputs;
  for (const float u : {4.0F, 4.0F, 4.0F, -8.0F, -8.0F, -8.0F}) {
    integrator.update(u, 0.5F, 0.25F, -1.5F, 1.0F);  // steps of u / 8
    outputs.push_back(integrator.output());
  }
  EXPECT_EQ(outputs, (std::vector<float>{0.5F, 1.0F, 1.0F, 0.0F, -1.0F, -1.5F}));
  // The float order is pinned too.
  EXPECT_NE((0.7F * 0.01F) * 0.1F, 0.7F * (0.01F * 0.1F));
  DiscreteIntegrator<float> pinned{0.0F};
  pinned.update(0.1F, 0.7F, 0.01F, -1.0F, 1.0F);
  EXPECT_EQ(pinned.output(), (0.7F * 0.01F) * 0.1F);
}

TEST(BlocksDiscreteDerivative, DividesTheScaledDifferenceByThePeriod) {
  const float gain = 0.7F;
  const float period = 0.01F;
  DiscreteDerivative<float> derivative{0.03F};
  float previous = 0.03F;
  for (const float u : {0.4F, 0.5F, 0.5F, -0.25F}) {
    EXPECT_EQ(derivative.output(u, gain, period), (gain * (u - previous)) / period);
    derivative.update(u);
    previous = u;
  }
  // Whole numbers: 2 * (4 - 1) / 0.5 = 12.
  DiscreteDerivative<double> exact{1.0};
  EXPECT_EQ(exact.output(4.0, 2.0, 0.5), 12.0);
  EXPECT_EQ(exact.output(4.0, 2.0, 0.5), 12.0);  // output() does not advance the state
  exact.update(4.0);
  EXPECT_EQ(exact.output(3.0, 2.0, 0.5), -4.0);
  // Other orders round differently for the pinned values.
  EXPECT_NE((gain * (0.4F - 0.03F)) / period, (gain / period) * (0.4F - 0.03F));
  EXPECT_NE((gain * (0.4F - 0.03F)) / period, gain * ((0.4F - 0.03F) / period));
}

TEST(BlocksDiscretePid, HandComputedStepsWithSaturation) {
  // Dyadic values, so every step is exact and can be checked by hand; N * Ts = 1.
  const PidGains<double> gains{.p = 2.0, .i = 4.0, .d = 0.5, .n = 4.0, .lower = -5.0, .upper = 5.0};
  DiscretePid<double> pid{0.0, 0.0};
  std::vector<double> outputs;
  for (const double error : {1.0, 0.5, -1.0, 2.0, 0.0}) {
    outputs.push_back(pid.output(error, gains));
    pid.update(error, gains, 0.25);
  }
  // step 0: D = 4 * (0.5 - 0) = 2;    y = 2 + 0 + 2 = 4;          F = 0.5;   I = 1
  // step 1: D = 4 * (0.25 - 0.5) = -1; y = 1 + 1 - 1 = 1;         F = 0.25;  I = 1.5
  // step 2: D = 4 * (-0.5 - 0.25) = -3; y = -2 + 1.5 - 3 = -3.5;  F = -0.5;  I = 0.5
  // step 3: D = 4 * (1 + 0.5) = 6;    y = 4 + 0.5 + 6 = 10.5 -> 5; F = 1;     I = 2.5
  // step 4: D = 4 * (0 - 1) = -4;     y = 0 + 2.5 - 4 = -1.5;     F = 0;     I = 2.5
  EXPECT_EQ(outputs, (std::vector<double>{4.0, 1.0, -3.5, 5.0, -1.5}));
  EXPECT_EQ(pid.integrator, 2.5);
  EXPECT_EQ(pid.filter, 0.0);
}

TEST(BlocksDiscretePid, AResetStepIsAtRestAndTheNextStartsFromRest) {
  // The gains of HandComputedStepsWithSaturation. The PID has run two steps (F = 0.25, I = 1.5), then a reset step
  // with e = -1: the output is that of a PID at rest, P e + N (D e - 0) = -2 - 2 = -4, and afterwards both states are
  // 0 (update() and update_clamped() alike). The next step, e = 1 without reset, is the first step from rest: 4.
  const PidGains<double> gains{.p = 2.0, .i = 4.0, .d = 0.5, .n = 4.0, .lower = -5.0, .upper = 5.0};
  for (const bool clamped : {false, true}) {
    DiscretePid<double> pid{0.0, 0.0};
    for (const double error : {1.0, 0.5}) {
      EXPECT_NE(pid.output(error, gains, false), 0.0);
      pid.update(error, gains, 0.25, false);
    }
    EXPECT_EQ(pid.integrator, 1.5);
    EXPECT_EQ(pid.filter, 0.25);
    EXPECT_EQ(pid.output(-1.0, gains, true), -4.0);
    EXPECT_EQ(pid.output(-1.0, gains, false), -2.0 + 1.5 + 4.0 * (-0.5 - 0.25));  // what it gives without the reset
    if (clamped) {
      pid.update_clamped(-1.0, gains, 0.25, true);
    } else {
      pid.update(-1.0, gains, 0.25, true);
    }
    EXPECT_EQ(pid.integrator, 0.0);
    EXPECT_EQ(pid.filter, 0.0);
    EXPECT_EQ(pid.output(1.0, gains, false), 4.0);  // step 0 of HandComputedStepsWithSaturation
  }
}

// The formulas of state.hpp written as plain expressions (C++ evaluates a * b * c as (a * b) * c and a + b + c as
// (a + b) + c; the test compiles without contraction, like duet_blocks' users). It also counts the steps where another
// order of evaluation would have given another output or integrator: where there are some, the comparison pins the
// order.
template <typename T>
struct ReferencePid {
  T integrator{};
  T filter{};
  int output_order_mattered = 0;
  int integrator_order_mattered = 0;

  T step(T error, const PidGains<T>& g, T period_s) {
    const auto limit = [&g](T value) { return value > g.upper ? g.upper : value < g.lower ? g.lower : value; };
    const T derivative = g.n * (g.d * error - filter);
    const T y = limit(g.p * error + integrator + derivative);
    if (y != limit(g.p * error + (integrator + derivative))) ++output_order_mattered;
    filter = filter + period_s * derivative;
    const T previous_integrator = integrator;
    integrator = integrator + period_s * (g.i * error);  // Simulink's order: the gain, then the integrator's Ts
    if (integrator != previous_integrator + g.i * period_s * error) ++integrator_order_mattered;
    return y;
  }
};

template <typename T>
ReferencePid<T> expect_pid_matches_reference(const PidGains<T>& gains, T period_s, const std::array<T, 5>& errors) {
  DiscretePid<T> pid{static_cast<T>(0.1), static_cast<T>(-0.05)};
  ReferencePid<T> reference{static_cast<T>(0.1), static_cast<T>(-0.05)};
  for (std::size_t step = 0; step < errors.size(); ++step) {
    const T y = pid.output(errors[step], gains);
    pid.update(errors[step], gains, period_s);
    EXPECT_EQ(y, reference.step(errors[step], gains, period_s)) << "step " << step;
    EXPECT_EQ(pid.integrator, reference.integrator) << "step " << step;
    EXPECT_EQ(pid.filter, reference.filter) << "step " << step;
  }
  return reference;
}

TEST(BlocksDiscretePid, MatchesTheReferenceBitForBitOverFiveSteps) {
  const auto in_double = expect_pid_matches_reference<double>(
      {.p = 1.3, .i = 5.0, .d = 0.11, .n = 30.0, .lower = -2.0, .upper = 2.0}, 0.01, {0.01, 0.45, -0.3, 1.7, 0.05});
  const auto in_float =
      expect_pid_matches_reference<float>({.p = 1.3F, .i = 5.0F, .d = 0.11F, .n = 30.0F, .lower = -2.0F, .upper = 2.0F},
                                          0.01F, {0.01F, 0.45F, -0.3F, 1.7F, 0.05F});
  EXPECT_GT(in_double.output_order_mattered + in_float.output_order_mattered, 0);
  EXPECT_GT(in_double.integrator_order_mattered + in_float.integrator_order_mattered, 0);
}

TEST(BlocksFilteredDerivative, HandComputedSteps) {
  // gain 0.5, N = 4, Ts = 0.25 (N * Ts = 1), filter from 0:
  // u = 1:  y = 4 * (0.5 - 0) = 2;       filter = 0 + 0.25 * 2 = 0.5
  // u = 1:  y = 4 * (0.5 - 0.5) = 0;     filter = 0.5
  // u = -1: y = 4 * (-0.5 - 0.5) = -4;   filter = 0.5 - 1 = -0.5
  // u = -1: y = 4 * (-0.5 + 0.5) = 0;    filter = -0.5
  FilteredDerivative<double> derivative{0.0};
  std::vector<double> outputs;
  for (const double u : {1.0, 1.0, -1.0, -1.0}) {
    outputs.push_back(derivative.output(u, 0.5, 4.0));
    derivative.update(u, 0.5, 4.0, 0.25);
  }
  EXPECT_EQ(outputs, (std::vector<double>{2.0, 0.0, -4.0, 0.0}));
  EXPECT_EQ(derivative.filter, -0.5);
  // gain 1, N = 4, Ts = 0.125 (N * Ts = 0.5): the filter approaches gain * u gradually.
  // u = 1: y = 4 * (1 - 0) = 4;    filter = 0 + 0.125 * 4 = 0.5
  // u = 1: y = 4 * (1 - 0.5) = 2;  filter = 0.5 + 0.125 * 2 = 0.75
  FilteredDerivative<float> gradual{0.0F};
  EXPECT_EQ(gradual.output(1.0F, 1.0F, 4.0F), 4.0F);
  gradual.update(1.0F, 1.0F, 4.0F, 0.125F);
  EXPECT_EQ(gradual.filter, 0.5F);
  EXPECT_EQ(gradual.output(1.0F, 1.0F, 4.0F), 2.0F);
  gradual.update(1.0F, 1.0F, 4.0F, 0.125F);
  EXPECT_EQ(gradual.filter, 0.75F);
}

TEST(BlocksFilteredDerivative, IsThePidsDerivativeBitForBit) {
  // A PID with only D and no limits computes add(add(0 * e, 0), derivative) = derivative (up to the sign of a zero).
  const PidGains<float> gains{.p = 0.0F, .i = 0.0F, .d = 0.11F, .n = 30.0F, .lower = -1e30F, .upper = 1e30F};
  DiscretePid<float> pid{0.0F, 0.013F};
  FilteredDerivative<float> derivative{0.013F};
  for (const float u : {0.01F, 0.45F, -0.3F, 1.7F, 0.05F}) {
    EXPECT_EQ(derivative.output(u, gains.d, gains.n), pid.output(u, gains));
    derivative.update(u, gains.d, gains.n, 0.01F);
    pid.update(u, gains, 0.01F);
    EXPECT_EQ(derivative.filter, pid.filter);
  }
}

struct PidRun {
  std::vector<double> outputs;
  std::vector<double> integrators;
};

PidRun run_pid(DiscretePid<double> pid, const PidGains<double>& gains, double period_s, bool clamped,
               std::initializer_list<double> errors) {
  PidRun run;
  for (const double error : errors) {
    run.outputs.push_back(pid.output(error, gains));
    if (clamped) {
      pid.update_clamped(error, gains, period_s);
    } else {
      pid.update(error, gains, period_s);
    }
    run.integrators.push_back(pid.integrator);
  }
  return run;
}

TEST(BlocksDiscretePidClamped, StopsIntegratingIntoSaturationAndComesBackAtOnce) {
  // P = 1, I = 1, no D (n = 0 keeps the filter at 0), Ts = 1, limits [-2, 2], integrator from 0. unlimited = e + I.
  const PidGains<double> gains{.p = 1.0, .i = 1.0, .d = 0.0, .n = 0.0, .lower = -2.0, .upper = 2.0};
  const auto errors = {1.0, 1.0, 1.0, 1.0, -1.0, -1.0};
  // clamped:  e = 1:  unlimited 1 + 0 = 1, inside          y = 1   I = 1
  //           e = 1:  unlimited 1 + 1 = 2, at the limit     y = 2   I = 2   (exactly at a limit integrates)
  //           e = 1:  unlimited 1 + 2 = 3 > 2, increment 1 > 0: clamped   y = 2   I = 2
  //           e = 1:  the same                              y = 2   I = 2
  //           e = -1: unlimited -1 + 2 = 1                  y = 1   I = 1
  //           e = -1: unlimited -1 + 1 = 0                  y = 0   I = 0
  const PidRun clamped = run_pid({0.0, 0.0}, gains, 1.0, true, errors);
  EXPECT_EQ(clamped.outputs, (std::vector<double>{1.0, 2.0, 2.0, 2.0, 1.0, 0.0}));
  EXPECT_EQ(clamped.integrators, (std::vector<double>{1.0, 2.0, 2.0, 2.0, 1.0, 0.0}));
  // update() winds up: I = 1, 2, 3, 4; then unlimited -1 + 4 = 3 stays saturated (y = 2, I = 3), then -1 + 3 = 2.
  const PidRun wound_up = run_pid({0.0, 0.0}, gains, 1.0, false, errors);
  EXPECT_EQ(wound_up.outputs, (std::vector<double>{1.0, 2.0, 2.0, 2.0, 2.0, 2.0}));
  EXPECT_EQ(wound_up.integrators, (std::vector<double>{1.0, 2.0, 3.0, 4.0, 3.0, 2.0}));
}

TEST(BlocksDiscretePidClamped, LowerLimitTooAndAnIncrementAgainstTheExcessIntegrates) {
  const PidGains<double> gains{.p = 1.0, .i = 1.0, .d = 0.0, .n = 0.0, .lower = -2.0, .upper = 2.0};
  // From I = -5: e = -1: unlimited -6 < -2, increment -1 < 0: clamped, y = -2, I = -5.
  //              e = 1:  unlimited -4 < -2 but increment 1 > 0 pulls out: y = -2, I = -4.
  //              e = 1:  unlimited -3: y = -2, I = -3;  e = 1: unlimited -2 (at the limit): y = -2, I = -2;
  //              e = 1:  unlimited -1: y = -1, I = -1.
  const PidRun lower = run_pid({-5.0, 0.0}, gains, 1.0, true, {-1.0, 1.0, 1.0, 1.0, 1.0});
  EXPECT_EQ(lower.outputs, (std::vector<double>{-2.0, -2.0, -2.0, -2.0, -1.0}));
  EXPECT_EQ(lower.integrators, (std::vector<double>{-5.0, -4.0, -3.0, -2.0, -1.0}));
  // Above the upper limit from I = 5 with e = -1: unlimited 4 > 2, increment -1 < 0: integrates, I = 4.
  const PidRun upper = run_pid({5.0, 0.0}, gains, 1.0, true, {-1.0, -1.0, -1.0, -1.0});
  EXPECT_EQ(upper.outputs, (std::vector<double>{2.0, 2.0, 2.0, 1.0}));  // unlimited 4, 3, 2, 1
  EXPECT_EQ(upper.integrators, (std::vector<double>{4.0, 3.0, 2.0, 1.0}));
}

TEST(BlocksDiscretePidClamped, TheIncrementsSignCountsNotTheErrors) {
  // A negative integral gain: e = 1 gives increment -1 * 1 * 1 = -1 while unlimited = 1 * 1 + 4 = 5 > 2, so
  // integrating pulls the output back toward the limit: not clamped, I = 3. e = -1: unlimited -1 + 3 = 2, at the
  // limit: I = 3 + 1 = 4. e = -1 again: unlimited 3 > 2 and increment +1 > 0: clamped, I = 4.
  const PidGains<double> gains{.p = 1.0, .i = -1.0, .d = 0.0, .n = 0.0, .lower = -2.0, .upper = 2.0};
  const PidRun run = run_pid({4.0, 0.0}, gains, 1.0, true, {1.0, -1.0, -1.0});
  EXPECT_EQ(run.outputs, (std::vector<double>{2.0, 2.0, 2.0}));
  EXPECT_EQ(run.integrators, (std::vector<double>{3.0, 4.0, 4.0}));
}

TEST(BlocksDiscretePidClamped, WithTheDerivativeTheFilterUpdatesAsWithoutClamping) {
  // The hand-computed run of HandComputedStepsWithSaturation, clamped: steps 0 to 2 are the same (no saturation);
  // step 3: D = 4 * (1 + 0.5) = 6, unlimited 4 + 0.5 + 6 = 10.5 > 5 with increment 4 * 0.25 * 2 = 2 > 0: clamped,
  //         y = 5, F = -0.5 + 0.25 * 6 = 1, I stays 0.5
  // step 4: D = 4 * (0 - 1) = -4, y = 0 + 0.5 - 4 = -3.5, F = 0, I = 0.5 + 0 = 0.5
  const PidGains<double> gains{.p = 2.0, .i = 4.0, .d = 0.5, .n = 4.0, .lower = -5.0, .upper = 5.0};
  DiscretePid<double> pid{0.0, 0.0};
  std::vector<double> outputs;
  for (const double error : {1.0, 0.5, -1.0, 2.0, 0.0}) {
    outputs.push_back(pid.output(error, gains));
    pid.update_clamped(error, gains, 0.25);
  }
  EXPECT_EQ(outputs, (std::vector<double>{4.0, 1.0, -3.5, 5.0, -3.5}));
  EXPECT_EQ(pid.integrator, 0.5);
  EXPECT_EQ(pid.filter, 0.0);
}

TEST(BlocksDiscretePidClamped, WithoutSaturationItIsUpdateBitForBit) {
  const PidGains<float> gains{.p = 1.3F, .i = 0.7F, .d = 0.11F, .n = 30.0F, .lower = -20.0F, .upper = 20.0F};
  DiscretePid<float> plain{0.1F, -0.05F};
  DiscretePid<float> clamped{0.1F, -0.05F};
  for (const float error : {0.01F, 0.45F, -0.3F, 1.7F, 0.05F}) {
    plain.update(error, gains, 0.01F);
    clamped.update_clamped(error, gains, 0.01F);
    EXPECT_EQ(clamped.integrator, plain.integrator);
    EXPECT_EQ(clamped.filter, plain.filter);
  }
}

TEST(BlocksCounter, CountsUpToTheLimitAndWraps) {
  Counter<std::uint8_t> counter{0};
  std::vector<int> outputs;
  for (int step = 0; step < 9; ++step) {
    outputs.push_back(counter.output());
    counter.update(3);
  }
  EXPECT_EQ(outputs, (std::vector<int>{0, 1, 2, 3, 0, 1, 2, 3, 0}));

  Counter<std::int16_t> lowered{5};
  lowered.update(3);  // above the new limit: restarts
  EXPECT_EQ(lowered.output(), 0);

  Counter<std::uint8_t> full_range{254};
  full_range.update(255);
  EXPECT_EQ(full_range.output(), 255);
  full_range.update(255);
  EXPECT_EQ(full_range.output(), 0);

  Counter<std::uint32_t> zero_limit{0};
  zero_limit.update(0);
  EXPECT_EQ(zero_limit.output(), 0U);
}

std::vector<bool> detect_all(Edge edge, bool initial, std::initializer_list<bool> inputs) {
  EdgeDetector<bool> detector{initial};
  std::vector<bool> found;
  for (const bool u : inputs) found.push_back(detector.detect(edge, u));
  return found;
}

TEST(BlocksEdgeDetector, BoolRisesFromFalseToTrueAndFallsBack) {
  const auto inputs = {true, true, false, false, true, false};
  EXPECT_EQ(detect_all(Edge::rising, false, inputs), (std::vector<bool>{true, false, false, false, true, false}));
  EXPECT_EQ(detect_all(Edge::falling, false, inputs), (std::vector<bool>{false, false, true, false, false, true}));
  EXPECT_EQ(detect_all(Edge::either, false, inputs), (std::vector<bool>{true, false, true, false, true, true}));
  EXPECT_EQ(detect_all(Edge::rising, true, inputs), (std::vector<bool>{false, false, false, false, true, false}));
}

TEST(BlocksEdgeDetector, FloatRisesAboveZeroAndFallsToZeroOrBelow) {
  const float nan_value = std::numeric_limits<float>::quiet_NaN();
  const std::array<float, 10> inputs{0.0F, 0.5F, 1.0F, -1.0F, 0.0F, 2.0F, 0.0F, 3.0F, nan_value, 1.0F};
  // 0 -> 0.5 rises, 1 -> -1 falls, -1 -> 0 is no edge (0 is not above 0), 0 -> 2 rises, 2 -> 0 falls, 0 -> 3 rises,
  // and nothing leads to or from NaN.
  const std::array<bool, 10> rising{false, true, false, false, false, true, false, true, false, false};
  const std::array<bool, 10> falling{false, false, false, true, false, false, true, false, false, false};
  EdgeDetector<float> rise{0.0F};
  EdgeDetector<float> fall{0.0F};
  EdgeDetector<float> either{0.0F};
  for (std::size_t step = 0; step < inputs.size(); ++step) {
    EXPECT_EQ(rise.detect(Edge::rising, inputs[step]), rising[step]) << "step " << step;
    EXPECT_EQ(fall.detect(Edge::falling, inputs[step]), falling[step]) << "step " << step;
    EXPECT_EQ(either.detect(Edge::either, inputs[step]), rising[step] || falling[step]) << "step " << step;
  }
  EXPECT_EQ(rise.previous, 1.0F);
}

TEST(BlocksEdgeDetector, SignedIntegers) {
  EdgeDetector<std::int8_t> detector{-3};
  EXPECT_FALSE(detector.detect(Edge::either, 0));
  EXPECT_TRUE(detector.detect(Edge::rising, 1));
  EXPECT_TRUE(detector.detect(Edge::falling, -128));
}

}  // namespace
}  // namespace duet::blocks
