// The tilt PID closed around the robot's linear model: the thesis' PD leaves a mode outside the unit circle, the
// rolling mode stays at 1 whatever the gains, and the design's loop is stable.
#include "duet/control/pid_design.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace duet::control {
namespace {

PidLoop robot_loop() {
  PidLoopSpec spec;
  spec.robot.volts_per_input = 7.4;  // the input is the duty
  spec.input_delay_s = 0.0005;
  spec.sensor_height_m = 0.075;
  auto loop = PidLoop::make(spec);
  EXPECT_TRUE(loop) << loop.error();
  return std::move(loop).value();
}

TEST(PidDesign, TheRollingModeIsAtOneForAnyGains) {
  const PidLoop loop = robot_loop();
  const Eigen::VectorXd mode = loop.rolling_mode();
  for (const PidLoopGains gains : {PidLoopGains{0.3, 8, 0.06, 28.234}, PidLoopGains{0.01, 0.5, 0.001, 100}}) {
    EXPECT_LT((loop.closed_loop(gains) * mode - mode).norm(), 1e-12);
  }
}

TEST(PidDesign, TheThesisPdGainsLeaveAnUnstableMode) {
  // The README's argument: without I, one real mode stays outside the unit circle (about 2.4 per second).
  const Eigen::VectorXcd modes = robot_loop().moving_eigenvalues({0.0196, 0, 0.0187, 28.234});
  EXPECT_GT(std::abs(modes(0)), 1.002);
  EXPECT_NEAR(std::log(std::abs(modes(0))) / 1e-3, 2.43, 0.05);
}

TEST(PidDesign, TheShippedGainsAreStable) {
  const Eigen::VectorXcd modes = robot_loop().moving_eigenvalues({0.3, 8, 0.06, 28.234});
  EXPECT_LT(std::abs(modes(0)), 1.0);
}

TEST(PidDesign, TheDesignedLoopIsStableAndWithinItsLimits) {
  const PidLoop loop = robot_loop();
  const PidCriterion criterion;
  auto design = design_pid(loop, criterion);
  ASSERT_TRUE(design) << design.error();
  const PidLoopGains& gains = design.value().gains;
  const PidEvaluation& evaluation = design.value().evaluation;
  EXPECT_TRUE(evaluation.within_limits);
  EXPECT_LT(std::abs(evaluation.moving_eigenvalues(0)), 1.0);
  EXPECT_LE(gains.p + gains.d * gains.n, criterion.maximum_high_frequency_gain);
  EXPECT_LT(evaluation.slowest_time_constant_s, 0.2);
  ASSERT_TRUE(evaluation.filter_mode.has_value());  // left out: the filter's, near 1
  EXPECT_GT(std::abs(*evaluation.filter_mode), 0.99998);
}

TEST(PidDesign, BadSpecificationsAreNamed) {
  PidLoopSpec spec;
  spec.input_delay_s = 0.002;
  auto loop = PidLoop::make(spec);
  ASSERT_FALSE(loop);
  EXPECT_EQ(loop.error(), "input_delay_s must be at least 0 and less than the period (0.001 s); it is 0.002");
}

}  // namespace
}  // namespace duet::control
