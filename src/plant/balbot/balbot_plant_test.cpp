// The robot as a whole: the registry, the truth columns, a closed loop through the sensor chain, determinism.

#include "duet/plant/balbot/balbot_plant.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "balbot_test_bench.hpp"

namespace duet::plant {
namespace {

using testing::balance;
using testing::BalbotBench;

double theta_deg(const std::array<double, BalbotTruth::count>& values) { return values[1]; }

TEST(BalbotPlant, IsMadeByName) {
  const std::vector<std::string> names = plant_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "balbot"), names.end());
  Result<std::unique_ptr<Plant>> made = make_plant("balbot", 7);
  ASSERT_TRUE(made.ok());
  EXPECT_NE(dynamic_cast<BalbotPlant*>(made.value().get()), nullptr);
  EXPECT_NE(make_plant("balbott", 7).error().find("did you mean 'balbot'"), std::string::npos);
}

TEST(BalbotPlant, TruthColumnsHaveANameEach) {
  const auto& names = BalbotTruth::names();
  EXPECT_EQ(names.front(), "time_s");
  EXPECT_EQ(names.back(), "duty_disturbance");
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_FALSE(names[i].empty());
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(names[i], names[j]);
  }
  BalbotBench bench;
  bench.drive_forward(40);
  bench.run_until(0.1);
  const BalbotTruth t = bench.plant.truth();
  const auto values = t.values();
  const auto column = [&](std::string_view name) {
    return values[static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin())];
  };
  EXPECT_EQ(column("time_s"), t.time_s);
  EXPECT_EQ(column("theta_deg"), t.theta_deg);
  EXPECT_EQ(column("left_mode"), 3);   // clockwise
  EXPECT_EQ(column("right_mode"), 4);  // counter-clockwise
  EXPECT_EQ(column("right_out1"), 0);
  EXPECT_EQ(column("right_out2"), 1);
  EXPECT_EQ(column("right_current_a"), t.right.current_a);
  EXPECT_EQ(column("battery_v"), t.battery_v);
  EXPECT_EQ(column("driver_standby"), 0);
}

TEST(BalbotPlant, UnknownResourcesAreRememberedOnce) {
  BalbotBench bench;
  bench.set("gpio:PE12", 1);
  bench.set("gpio:PE12", 0);
  EXPECT_EQ(bench.get("capture:TIM3/1"), 0);
  EXPECT_EQ(bench.plant.unknown_resources(), (std::vector<std::string>{"gpio:PE12", "capture:TIM3/1"}));
}

TEST(BalbotPlant, ASecondSpiTransactionBeforeTheFirstsDmaCompletedIsRefused) {
  BalbotBench bench;
  bench.spi({0x75 | 0x80, 0});
  bench.spi({0x1B, 0x18});
  EXPECT_EQ(bench.plant.refused_spi_transactions(), 1U);
  bench.run_until(0.001);
  EXPECT_EQ(bench.get("spi:SPI5", 2)[1], 0x70);
}

TEST(BalbotPlant, ASensorFeedbackControllerBalancesTheRobotAndCatchesAPush) {
  BalbotScenario scenario;  // with noise
  scenario.initial_tilt_deg = 2;
  scenario.pushes = {{.time_s = 3.0, .force_n = 1.0, .duration_s = 0.1}};
  const auto truth = balance(scenario, 6.0);
  double largest_late = 0;
  for (std::size_t tick = 2000; tick < truth.size(); ++tick) {
    largest_late = std::max(largest_late, std::abs(theta_deg(truth[tick])));
  }
  EXPECT_LT(largest_late, 6);  // the push tips it a few degrees; it stays up
  EXPECT_LT(std::abs(theta_deg(truth.back())), 1.5);
}

TEST(BalbotPlant, TheSameSeedGivesTheSameRunAndAnotherSeedAnother) {
  BalbotScenario scenario;
  scenario.initial_tilt_deg = 2;
  scenario.seed = 11;
  const auto first = balance(scenario, 1.5);
  const auto second = balance(scenario, 1.5);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t tick = 0; tick < first.size(); ++tick) ASSERT_EQ(first[tick], second[tick]) << tick;
  scenario.seed = 12;
  const auto other = balance(scenario, 1.5);
  EXPECT_NE(theta_deg(other.back()), theta_deg(first.back()));
}

TEST(BalbotPlant, ADutyDisturbancePulseActsOnBothMotors) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.rig = BalbotRig::held_in_air;
  scenario.duty_disturbances = {{.time_s = 0.010, .duty = 1.0, .duration_s = 0.001}};  // fig. 5.71: 1 ms of 1
  BalbotBench bench{scenario};
  // The motor logic with a manipulated variable of 0: a direction selected, duty 0 (short brake).
  bench.drive_forward(0);
  bench.run_until(0.010);
  EXPECT_EQ(bench.plant.truth().left.mode, MotorMode::clockwise);
  EXPECT_EQ(bench.plant.truth().duty_disturbance, 1.0);
  EXPECT_GT(bench.plant.truth().left.current_a, 1);
  EXPECT_LT(bench.plant.truth().right.current_a, -1);  // mirrored: forward is counter-clockwise
  bench.run_until(0.011);
  EXPECT_EQ(bench.plant.truth().left.mode, MotorMode::short_brake);
  EXPECT_GT(bench.plant.truth().wheel_rev_s, 0.05);  // the pulse turned the wheels forward
}

}  // namespace
}  // namespace duet::plant
