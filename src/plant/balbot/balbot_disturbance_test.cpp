// Disturbances asked for during a run (BalbotPlant::disturb): the scenario's own, at the time asked; and the
// restart, which picks the robot up, puts it back as the scenario starts it, holds it and lets it go.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "balbot_test_bench.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"

namespace duet::plant {
namespace {

using testing::balance;
using testing::BalancingController;
using testing::BalbotBench;
using Rows = std::vector<std::array<double, BalbotTruth::count>>;

std::size_t column(std::string_view name) {
  const auto& names = BalbotTruth::names();
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}
double at(const Rows& rows, double time_s, std::string_view name) {
  return rows.at(static_cast<std::size_t>(std::llround(time_s * 1000))).at(column(name));
}

TEST(BalbotDisturbances, TheRobotOffersPushDutyPulseAndRestart) {
  const std::vector<DisturbanceKind> kinds = BalbotPlant{}.disturbances();
  ASSERT_EQ(kinds.size(), 3U);
  EXPECT_EQ(kinds[0].name, "push");
  ASSERT_EQ(kinds[0].arguments.size(), 2U);
  EXPECT_EQ(kinds[0].arguments[0].name, "force_n");
  EXPECT_EQ(kinds[0].arguments[0].unit, "N");
  EXPECT_EQ(kinds[0].arguments[0].default_value, 5);
  EXPECT_EQ(kinds[0].arguments[1].name, "duration_s");
  EXPECT_EQ(kinds[1].name, "duty_pulse");
  EXPECT_EQ(kinds[2].name, "restart");
  EXPECT_TRUE(kinds[2].arguments.empty());
  for (const DisturbanceKind& kind : kinds) {
    for (const DisturbanceArgument& argument : kind.arguments) {
      EXPECT_LE(argument.minimum, argument.default_value) << kind.name << " " << argument.name;
      EXPECT_LE(argument.default_value, argument.maximum) << kind.name << " " << argument.name;
    }
  }
}

TEST(BalbotDisturbances, APushAskedForAtATickIsTheScenariosPushAtThatTime) {
  // A noisy closed loop through the whole sensor chain, so that any difference would grow and show.
  BalbotScenario planned;
  planned.initial_tilt_deg = 2;
  const double push_at = 2500 * 1e-3;  // the time of tick 2500, as the simulation computes it
  const double pulse_at = 3200 * 1e-3;
  BalbotScenario scenario = planned;
  scenario.pushes = {{.time_s = push_at, .force_n = 1.5, .duration_s = 0.08}};
  scenario.duty_disturbances = {{.time_s = pulse_at, .duty = 1.0, .duration_s = 0.001}};
  const Rows in_the_scenario = balance(scenario, 4.0);
  const Rows asked_for = balance(planned, 4.0, [&](double now, BalbotPlant& plant, const BalancingController&) {
    // Between the ticks before and at those times, as PlantControls hands them over.
    if (std::llround(now * 1000) == 2499) plant.disturb({"push", {1.5, 0.08}}, push_at);
    if (std::llround(now * 1000) == 3199) plant.disturb({"duty_pulse", {1.0, 0.001}}, pulse_at);
  });
  ASSERT_EQ(in_the_scenario.size(), asked_for.size());
  for (std::size_t tick = 0; tick < asked_for.size(); ++tick) ASSERT_EQ(in_the_scenario[tick], asked_for[tick]) << tick;
  EXPECT_EQ(at(asked_for, 2.55, "push_force_n"), 1.5);
  EXPECT_EQ(at(asked_for, 2.58, "push_force_n"), 0.0);
  EXPECT_EQ(at(asked_for, 3.2, "duty_disturbance"), 1.0);
  const Rows undisturbed = balance(planned, 4.0);  // and they did something
  EXPECT_GT(std::abs(at(asked_for, 2.7, "theta_deg") - at(undisturbed, 2.7, "theta_deg")), 0.3);
}

TEST(BalbotDisturbances, RestartPicksTheFallenRobotUpPutsItBackHoldsItAndLetsGo) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.initial_tilt_deg = 5;
  scenario.release_time_s = 0.5;
  scenario.pushes = {{.time_s = 0.2, .force_n = 3, .duration_s = 0.05}};  // while held: shows, moves nothing
  BalbotBench bench{scenario};
  bench.record = false;
  Rows rows;
  const double restart_at = 2001 * 1e-3;
  bench.run_until(3.8, [&](double now) {
    rows.push_back(bench.plant.truth().values());
    if (std::llround(now * 1000) == 2000) bench.plant.disturb({"restart", {}}, restart_at);
  });
  const double put_back = restart_at + 1;
  // Released without a controller at 0.5 s, it fell and lies on the floor.
  EXPECT_GT(at(rows, 2.0, "theta_deg"), 90);
  const double x_then = at(rows, restart_at, "x_m");
  // Carried: the axle stays, the wheels stop rolling, the body turns back with a rate that never jumps.
  double largest_rate_step = 0;
  for (double t = restart_at; t <= put_back; t += 0.001) {
    EXPECT_EQ(at(rows, t, "x_m"), x_then) << t;
    EXPECT_EQ(at(rows, t, "v_m_s"), 0.0) << t;
    largest_rate_step =
        std::max(largest_rate_step, std::abs(at(rows, t + 0.001, "theta_dot_deg_s") - at(rows, t, "theta_dot_deg_s")));
  }
  EXPECT_LT(largest_rate_step, 1.0);  // deg/s per millisecond: a hand, not a jolt
  EXPECT_LT(at(rows, restart_at + 0.5, "theta_deg"), at(rows, restart_at, "theta_deg") - 30);
  // Put back at the scenario's tilt, at rest, and held still as the scenario holds it until its release 0.5 s later.
  EXPECT_NEAR(at(rows, put_back, "theta_deg"), 5, 1e-9);
  EXPECT_NEAR(at(rows, put_back, "theta_dot_deg_s"), 0, 1e-9);
  EXPECT_EQ(at(rows, put_back + 0.49, "theta_deg"), at(rows, put_back, "theta_deg"));
  EXPECT_EQ(at(rows, put_back + 0.49, "x_m"), x_then);
  // The scenario's push comes again, 0.2 s after the robot is put back.
  EXPECT_EQ(at(rows, put_back + 0.19, "push_force_n"), 0.0);
  EXPECT_EQ(at(rows, put_back + 0.21, "push_force_n"), 3.0);
  EXPECT_EQ(at(rows, put_back + 0.26, "push_force_n"), 0.0);
  // Let go, it falls again: nobody balances it here.
  EXPECT_GT(at(rows, put_back + 0.51, "theta_deg"), 5.0);
  EXPECT_GT(at(rows, put_back + 0.79, "theta_deg"), 20.0);
}

TEST(BalbotDisturbances, AfterARestartAControllerFollowingTheGyroscopeBalancesAgain) {
  // The test controller's tilt follows the gyroscope (0.998 per millisecond), as the firmware's Kalman filter does:
  // knocked over, it must see the robot carried back up and take over when it is let go.
  BalbotScenario scenario;
  scenario.initial_tilt_deg = 2;
  double estimate_at_put_back = 0;
  const Rows rows = balance(scenario, 7.0, [&](double now, BalbotPlant& plant, const BalancingController& controller) {
    const auto tick = std::llround(now * 1000);
    if (tick == 1999) plant.disturb({"push", {40, 0.1}}, 2.0);  // too much to catch
    if (tick == 3999) plant.disturb({"restart", {}}, 4.0);
    if (tick == 5000) estimate_at_put_back = controller.theta();
  });
  EXPECT_GT(std::abs(at(rows, 3.9, "theta_deg")), 60);  // it fell
  EXPECT_NEAR(at(rows, 5.0, "theta_deg"), 2, 1e-9);     // put back, and let go at once (no release time)
  EXPECT_NEAR(estimate_at_put_back, 2, 1.0);
  double largest_late = 0;
  for (double t = 5.5; t <= 7.0; t += 0.001) largest_late = std::max(largest_late, std::abs(at(rows, t, "theta_deg")));
  EXPECT_LT(largest_late, 6);
}

}  // namespace
}  // namespace duet::plant
