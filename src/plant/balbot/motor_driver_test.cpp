#include "motor_driver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "balbot_test_bench.hpp"

namespace duet::plant {
namespace {

using testing::BalbotBench;

struct Row {
  int in1, in2, pwm, standby;
  PinLevel out1, out2;
  MotorMode mode;
};

constexpr PinLevel lo = PinLevel::low;
constexpr PinLevel hi = PinLevel::high;
constexpr PinLevel off = PinLevel::off;

// Thesis table 5.8 / balbot.md, every combination (x = both values); PWM H is a duty above 0.
constexpr Row table[] = {
    {1, 1, 1, 1, lo, lo, MotorMode::short_brake},
    {1, 1, 0, 1, lo, lo, MotorMode::short_brake},
    {0, 1, 1, 1, lo, hi, MotorMode::counter_clockwise},
    {0, 1, 0, 1, lo, lo, MotorMode::short_brake},
    {1, 0, 1, 1, hi, lo, MotorMode::clockwise},
    {1, 0, 0, 1, lo, lo, MotorMode::short_brake},
    {0, 0, 1, 1, off, off, MotorMode::stop},
    {0, 0, 0, 1, off, off, MotorMode::stop},
    {0, 0, 0, 0, off, off, MotorMode::standby},
    {0, 0, 1, 0, off, off, MotorMode::standby},
    {0, 1, 0, 0, off, off, MotorMode::standby},
    {0, 1, 1, 0, off, off, MotorMode::standby},
    {1, 0, 0, 0, off, off, MotorMode::standby},
    {1, 0, 1, 0, off, off, MotorMode::standby},
    {1, 1, 0, 0, off, off, MotorMode::standby},
    {1, 1, 1, 0, off, off, MotorMode::standby},
};

TEST(BalbotDriver, EveryInputCombinationGivesTheTruthTablesModeAndOutputs) {
  for (const Row& row : table) {
    BalbotScenario scenario = BalbotBench::quiet();
    scenario.rig = BalbotRig::held_in_air;
    BalbotBench bench{scenario};
    // Both motors get the same inputs: left on BIN1/BIN2/PWMB, right on AIN1/AIN2/PWMA.
    bench.set("gpio:PA12", row.standby);
    bench.set("gpio:PE9", row.in1);
    bench.set("gpio:PD1", row.in2);
    bench.set("pwm:TIM1/4", row.pwm * 60.0);
    bench.set("gpio:PE10", row.in1);
    bench.set("gpio:PD14", row.in2);
    bench.set("pwm:TIM1/3", row.pwm * 60.0);
    bench.run_until(0.2);
    const BalbotTruth t = bench.plant.truth();
    const std::string name = "IN1 " + std::to_string(row.in1) + " IN2 " + std::to_string(row.in2) + " PWM " +
                             std::to_string(row.pwm) + " STBY " + std::to_string(row.standby);
    for (const MotorTruth* motor : {&t.left, &t.right}) {
      EXPECT_EQ(motor->mode, row.mode) << name;
      EXPECT_EQ(motor->out1, row.out1) << name;
      EXPECT_EQ(motor->out2, row.out2) << name;
      // The motors are mirrored: the same inputs turn them against each other, so the wheels stand still and a
      // driven winding carries its stall current.
      const double volts = row.mode == MotorMode::clockwise ? 0.6 : row.mode == MotorMode::counter_clockwise ? -0.6 : 0;
      EXPECT_NEAR(motor->voltage_v, volts * t.battery_v, 1e-9) << name;
      EXPECT_NEAR(motor->current_a, volts * t.battery_v / 4.0, 1e-9) << name;
      EXPECT_EQ(motor->speed_rev_s, 0) << name;
    }
    EXPECT_EQ(t.driver_standby, row.standby == 0) << name;
  }
}

TEST(BalbotDriver, ADisturbanceIsAddedToTheForwardDuty) {
  const balbot::DriverInputs clockwise{.standby_high = true, .in1 = true, .in2 = false, .duty = 0.2};
  EXPECT_DOUBLE_EQ(balbot::tb6612fng(clockwise, 0.5, true).drive.drive, 0.7);
  EXPECT_DOUBLE_EQ(balbot::tb6612fng(clockwise, 0.5, false).drive.drive, -0.3);  // mirrored: forward is -
  EXPECT_EQ(balbot::tb6612fng(clockwise, -0.5, true).mode, MotorMode::counter_clockwise);
  EXPECT_DOUBLE_EQ(balbot::tb6612fng(clockwise, 1.0, true).drive.drive, 1.0);  // at most full duty
  const balbot::DriverInputs stopped{.standby_high = true, .in1 = false, .in2 = false, .duty = 0.2};
  EXPECT_FALSE(balbot::tb6612fng(stopped, 0.5, true).drive.connected);  // the outputs stay off
}

TEST(BalbotMotor, NoLoadWheelSpeedAtFullDutyIsTheThesis4_43RevPerSecond) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.rig = BalbotRig::held_in_air;
  BalbotBench bench{scenario};
  bench.drive_forward(100);
  bench.run_until(0.001);
  EXPECT_LT(bench.plant.truth().battery_v, 7.0);  // the starting current sags the battery
  bench.run_until(1.0);
  const BalbotTruth t = bench.plant.truth();
  EXPECT_NEAR(t.wheel_rev_s, 4.43, 4.43 * 0.02);
  EXPECT_NEAR(t.left.speed_rev_s, 30 * t.wheel_rev_s, 1e-9);
  EXPECT_NEAR(t.right.speed_rev_s, -30 * t.wheel_rev_s, 1e-9);
  EXPECT_NEAR(t.left.current_a, 0.1, 0.01);  // the no-load current: friction
  EXPECT_NEAR(t.battery_v, 7.4 - 0.2 * 2 * t.left.current_a, 1e-9);
}

TEST(BalbotMotor, RatedOutputIsAboutThreeWatts) {
  // One motor at full duty on the nominal battery, its wheel turned at each speed: the largest mechanical output.
  const BalbotParameters p;
  double best = 0;
  for (int step = 2; step < 89; ++step) {
    const double rev_s = 0.05 * step;
    BalbotScenario scenario = BalbotBench::quiet();
    scenario.rig = BalbotRig::wheels_driven;
    scenario.driven_wheel_rev_s = rev_s;
    BalbotBench bench{scenario};
    bench.set("gpio:PA12", 1);
    bench.set("gpio:PE9", 1);
    bench.set("pwm:TIM1/4", 100);
    bench.run_until(0.001);
    const MotorTruth left = bench.plant.truth().left;
    const double motor_rad_s = left.speed_rev_s * 2 * std::numbers::pi;
    const double power =
        (p.motor_constant_v_s_rad * left.current_a - p.motor_friction_n_m_s_rad * motor_rad_s) * motor_rad_s;
    best = std::max(best, power);
  }
  EXPECT_NEAR(best, 3.0, 0.15);
}

}  // namespace
}  // namespace duet::plant
