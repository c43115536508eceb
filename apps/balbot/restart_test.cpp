// The robot's controller model against the simulated robot, disturbed during the run as the dashboard's Disturb box
// does it (PlantControls): knocked over by a push, restarted, it is carried back up, held, let go and balanced
// again, its tilt estimate having followed the carry through the gyroscope: with the LQR and with the default PID.
// (Both drive back to where they started, the firmware keeping the position it counted. The LQR: restarted after
// rolling 1.8 m on its face it makes it; after 3.6 m its position term saturates the duty and it falls again.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/plant/plant_controls.hpp"

namespace duet::model {
namespace {

// Balanced from 5 degrees, knocked over at 4 s, restarted as it lands; `use_lqr` 1 for the LQR, 0 for the PID.
void knocked_over_then_restarted(double use_lqr_value) {
  auto model = load_model(DUET_BALBOT_MODEL);
  ASSERT_TRUE(model.ok()) << model.error();
  ProgramBuild build = build_program(model.value());
  ASSERT_TRUE(build.program.has_value());
  plant::BalbotScenario scenario;  // held at 5 degrees while the sensor starts, let go at 2 s
  scenario.initial_tilt_deg = 5;
  scenario.release_time_s = 2;
  plant::PlantControls controls{plant::BalbotPlant{}.disturbances()};
  plant::ControlledPlant robot{plant::make_balbot_plant(scenario), controls};
  const auto& parameters = model.value().parameters;
  const auto use_lqr = std::find_if(parameters.begin(), parameters.end(),
                                    [](const Parameter& parameter) { return parameter.name == "use_lqr"; });
  ASSERT_NE(use_lqr, parameters.end());

  SimulationOptions options;
  options.duration_s = 16;
  options.before_tick = [&](std::uint64_t tick, Interpreter& interpreter) {
    if (tick == 0) interpreter.set_parameter(static_cast<std::size_t>(use_lqr - parameters.begin()), 0, use_lqr_value);
    const auto ask = [&](plant::Disturbance disturbance) {
      ASSERT_TRUE(controls.request(std::move(disturbance), [](const Result<plant::AppliedDisturbance>&) {}).ok());
    };
    if (tick == 4000) ask({"push", {50, 0.15}});  // too much to catch: it falls forwards
    if (tick == 4600) ask({"restart", {}});       // as it lands: carried back up by 5.6 s, held until 7.6 s
  };
  auto simulated = simulate(*build.program, robot, options);
  ASSERT_TRUE(simulated.ok()) << simulated.error();
  const Recording& recording = simulated.value().recording;
  const auto column = [&](const std::string& name) -> const std::vector<double>& {
    const auto found = std::find(recording.names.begin(), recording.names.end(), name);
    EXPECT_NE(found, recording.names.end()) << name;
    return recording.columns.at(static_cast<std::size_t>(found - recording.names.begin()));
  };
  const auto at = [&](const std::string& name, double time_s) {
    return column(name).at(static_cast<std::size_t>(std::llround(time_s * 1000)));
  };
  const auto largest = [&](const std::string& name, double from_s, double to_s) {
    double result = 0;
    for (double t = from_s; t <= to_s; t += 0.001) result = std::max(result, std::abs(at(name, t)));
    return result;
  };

  const auto applied = controls.applied();
  ASSERT_EQ(applied.size(), 2U);
  EXPECT_EQ(applied[0].time_s, 4.0);
  EXPECT_DOUBLE_EQ(applied[1].time_s, 4.6);
  EXPECT_LT(at("plant.theta_deg", 4.6), -90.0);                       // it fell on its face
  EXPECT_EQ(at("stop", 4.6), 1.0);                                    // and the safety stop holds the motors
  EXPECT_NEAR(at("plant.theta_deg", 5.6), 5.0, 1e-9);                 // put back at the scenario's tilt
  EXPECT_EQ(at("plant.theta_deg", 7.5), at("plant.theta_deg", 5.6));  // held
  // The firmware's estimate followed the carry through the gyroscope, which it trusts (the accelerometer, little):
  // it moved as the body did (what it got wrong in the fall, it keeps).
  const double carried = at("plant.theta_deg", 5.6) - at("plant.theta_deg", 4.6);
  EXPECT_NEAR(at("theta", 5.6) - at("theta", 4.6), carried, 1.0);  // of 103 degrees
  EXPECT_NEAR(at("theta", 7.5), 5.0, 2.0);
  EXPECT_EQ(largest("stop", 5.6, 16), 0.0);
  EXPECT_LT(largest("plant.theta_deg", 10, 16), 5.0);  // let go at 7.6 s, balanced again
  EXPECT_LT(largest("plant.theta_deg", 13, 16), 1.0);
}

TEST(BalbotRestart, KnockedOverThenRestartedTheLqrBalancesItAgain) { knocked_over_then_restarted(1); }

TEST(BalbotRestart, KnockedOverThenRestartedThePidBalancesItAgain) { knocked_over_then_restarted(0); }

}  // namespace
}  // namespace duet::model
