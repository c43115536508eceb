// The import of the hand-written test models: what each block becomes, the model duet checks and simulates, values
// against what Simulink's blocks compute by their documentation, and refusals with the block's path and reason.
#include "duet/simulink_import/import.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <set>

#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/plant/plant.hpp"
#include "duet/simulink_import/simulink_file.hpp"
#include "duet/simulink_import/slx_model.hpp"
#include "duet/support/temporary_folder.hpp"
#include "duet/support/text_file.hpp"
#include "testing/import_harness.hpp"
#include "testing/package_folder.hpp"

namespace duet::simulink_import {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path testing = DUET_SIMULINK_TESTING_DIR;

TEST(Import, TheTiltLoopBecomesAModelThatChecksAndComputesWhatSimulinkDoes) {
  const SimulinkModel model = read_slx_model(parts_of(testing / "slx_r2019b"), "tilt_loop.slx").value();
  ImportOptions options;
  options.variables["Ts"] = Value::scalar(0.01);
  options.variables["Kp"] = Value::scalar(2);
  const ImportResult imported = import_simulink(model, options);
  ASSERT_TRUE(imported.problems.empty()) << ::testing::PrintToString(imported.problems);
  EXPECT_THAT(imported.model_text, HasSubstr("base_period_us: 10000\n"));
  EXPECT_THAT(imported.model_text, HasSubstr("  Kp: {value: 2, description: "));  // tunable, by its name
  EXPECT_EQ(verdict(imported, "tilt_loop/Proportional\nGain").what, "Gain k: Kp");
  EXPECT_EQ(verdict(imported, "tilt_loop/Scale/times k").what, "Gain k: 2.5");  // the mask's value, a literal
  EXPECT_EQ(verdict(imported, "tilt_loop/error").what, "Sum +-");
  EXPECT_EQ(verdict(imported, "tilt_loop/theta").what, "Inport (on its own the plant's inport:theta)");

  auto parsed = model::parse_model(imported.model_text, "tilt_loop.yaml");
  ASSERT_TRUE(parsed) << parsed.error() << "\n" << imported.model_text;
  const model::ProgramBuild build = model::build_program(parsed.value());
  for (const model::Diagnostic& diagnostic : build.diagnostics)
    ADD_FAILURE() << model::format("tilt_loop.yaml", diagnostic) << "\n" << imported.model_text;
  ASSERT_TRUE(build.program);
  // error = reference - theta (the Sum's first input is port 1, the reference), command = Kp error, duty = 2.5
  // command, previous = command a step late (UnitDelay from 0).
  Ports plant{{{"inport:theta", 1.0}, {"inport:reference", 3.0}}};
  auto simulated = model::simulate(*build.program, plant, {.duration_s = 0.02, .record_plant = false});
  ASSERT_TRUE(simulated) << simulated.error();
  EXPECT_EQ(plant.written.at("outport:duty"), 10.0);
  EXPECT_EQ(plant.written.at("outport:previous"), 4.0);
}

// Every block of the R2021a test model on a constant input u = 2, each value as Simulink's block computes it.
TEST(Import, EachBlockComputesWhatItsSimulinkBlockDoes) {
  const auto model = read_slx_model(parts_of(testing / "slx_r2021a"), "signal_chain.slx");
  ASSERT_TRUE(model) << model.error();
  const ImportResult imported = import_simulink(model.value(), {});
  std::unique_ptr<model::Model> keep;
  const auto build = checked(imported, keep);
  ASSERT_TRUE(build);
  Ports plant{{{"inport:u", 2.0}}};
  auto simulated = model::simulate(*build->program, plant, {.duration_s = 0.4, .record_plant = false});
  ASSERT_TRUE(simulated) << simulated.error();
  const auto steps = [&plant](const std::string& outport) { return plant.history.at("outport:y_" + outport); };
  using Steps = std::vector<double>;
  EXPECT_EQ(steps("product"), Steps(5, 6.0));                  // u * c
  EXPECT_EQ(steps("difference"), Steps(5, 3.0));               // product - c
  EXPECT_EQ(steps("magnitude"), Steps(5, 3.0));                // |c - product|
  EXPECT_EQ(steps("direction"), Steps(5, -1.0));               // sign(c - product)
  EXPECT_EQ(steps("limited"), Steps(5, 5.0));                  // 6 limited to [-5, 5]
  EXPECT_EQ(steps("largest"), Steps(5, 3.0));                  // max(u, c)
  EXPECT_EQ(steps("choice"), Steps(5, 6.0));                   // u2 = u = 2 > 1.5: the first input
  EXPECT_EQ(steps("truncated"), Steps(5, 1.0));                // int16(1.5), toward zero
  EXPECT_EQ(steps("late"), (Steps{7, 7, 7, 2, 2}));            // three steps late, from 7
  EXPECT_EQ(steps("lag"), (Steps{0, 2, 3, 3.5, 3.75}));        // 1 / (z - 0.5): y(k) = 0.5 y(k-1) + u(k-1)
  EXPECT_EQ(steps("state_lag"), (Steps{0, 2, 3, 3.5, 3.75}));  // the same as x(k+1) = 0.5 x + u, y = x
  const Steps ramp = steps("ramp");                            // forward Euler: y(k) = y(k-1) + 1 * 0.1 * u(k-1)
  ASSERT_EQ(ramp.size(), 5U);
  for (std::size_t k = 0; k < ramp.size(); ++k) EXPECT_NEAR(ramp[k], 0.2 * static_cast<double>(k), 1e-12) << k;
  EXPECT_EQ(steps("first"), Steps(5, 2.0));  // Mux then Demux
  EXPECT_EQ(steps("second"), Steps(5, 3.0));
  EXPECT_EQ(steps("tagged"), Steps(5, 3.0));                      // through Goto and From
  EXPECT_EQ(steps("less"), Steps(5, 1.0));                        // u < c
  EXPECT_EQ(steps("beyond"), Steps(5, 1.0));                      // 2 beyond the dead zone [-1, 1]: 2 - 1
  EXPECT_EQ(steps("looked_up"), Steps(5, 20.0));                  // between (1, 10) and (4, 40): 10 + 30 * (2 - 1) / 3
  EXPECT_NEAR(steps("angle")[0], std::atan2(2.0, 3.0), 1e-13);    // atan2(u, c)
  EXPECT_EQ(steps("squared"), Steps(5, 4.0));                     // u^2
  EXPECT_EQ(steps("inverse"), Steps(1, 1.0 / 3.0));               // 1 / c: of constants, so computed and written once
  EXPECT_EQ(steps("slope"), (Steps{20, 0, 0, 0, 0}));             // (u(k) - u(k-1)) / 0.1 from a previous 0
  EXPECT_EQ(steps("filtered"), (Steps{2, 3, 3.5, 3.75, 3.875}));  // 1 / (1 - 0.5 z^-1): y(k) = 0.5 y(k-1) + u(k)
  EXPECT_EQ(steps("matrix"), Steps(5, 8.0));
  EXPECT_EQ(steps("picked"), Steps(5, 3.0));    // [u c]([2 1]) = [c u]: its first element, c
  EXPECT_EQ(steps("both"), Steps(5, 0.0));      // less NAND less: not (true and true)
  const Steps limited = steps("limited_ramp");  // the ramp's state held within [-0.3, 0.3]
  ASSERT_EQ(limited.size(), 5U);
  EXPECT_NEAR(limited[1], 0.2, 1e-12);
  EXPECT_EQ(limited[2], 0.3);
  EXPECT_EQ(limited[4], 0.3);
  EXPECT_EQ(plant.history.at("outport:y_held"), Steps(3, 2.0));  // at 0.2 s: steps 0, 2 and 4 of 0.1 s //
                                                                 // [1 2; 3 4] * [u; c], the first element
  EXPECT_EQ(verdict(imported, "signal_chain/late").what, "3 UnitDelays in a row");
  EXPECT_EQ(verdict(imported, "signal_chain/end").what, "nothing to bring over");
}

// The oldest layout (R2014a): configuration set and BlockParameterDefaults inline in blockdiagram.xml, the mask as a
// MaskObject; the mask's value names a variable, evaluated outside the subsystem. y(k) = u(k) + 0.5 y(k-1).
TEST(Import, TheOldestLayoutWithItsInlineDefaultsConfigurationAndMaskObject) {
  const auto model = read_slx_model(parts_of(testing / "slx_r2014a"), "scaled_lag.slx");
  ASSERT_TRUE(model) << model.error();
  EXPECT_EQ(model.value().release, "R2014a");
  EXPECT_EQ(model.value().defaults.at("Sum").at("Inputs"), "++");
  EXPECT_EQ(model.value().solver.parameters.at("FixedStep"), "0.002");
  ImportOptions options;
  options.variables["pole"] = Value::scalar(0.5);
  const ImportResult imported = import_simulink(model.value(), options);
  std::unique_ptr<model::Model> keep;
  const auto build = checked(imported, keep);
  ASSERT_TRUE(build);
  EXPECT_THAT(imported.model_text, HasSubstr("base_period_us: 2000\n"));
  EXPECT_EQ(verdict(imported, "scaled_lag/Lag/pole").what, "Gain k: 0.5");  // the mask's a, a literal
  Ports plant{{{"inport:u", 1.0}}};
  ASSERT_TRUE(model::simulate(*build->program, plant, {.duration_s = 0.006, .record_plant = false}));
  EXPECT_EQ(plant.history.at("outport:y"), (std::vector<double>{1, 1.5, 1.75, 1.875}));
}

// The balancing loop of the thesis' robot as a Simulink model (testing/tilt_controller_r2022b with its variables,
// tilt_controller.m): a Kalman filter of Gain, Sum and UnitDelay blocks, a 10 ms outer loop behind rate transitions,
// the discrete PID with clamping, the duty's limit, and a triggered subsystem counting falls. It imports and checks,
// its variables tunable parameters of their names.
TEST(Import, TheBalancingLoopImportsAndChecks) {
  const ImportResult imported = imported_with(
      read_slx_model(parts_of(testing / "tilt_controller_r2022b"), "tilt_controller.slx"), "tilt_controller.m");
  std::unique_ptr<model::Model> keep;
  const auto build = checked(imported, keep);
  ASSERT_TRUE(build);
  for (const char* tunable : {"  P: {value: 0.3", "  kalman_L: {value: [[0.005728086339372147", "  stop_angle: "})
    EXPECT_THAT(imported.model_text, HasSubstr(tunable));
  EXPECT_EQ(verdict(imported, "tilt_controller/tilt PID").what, "DiscretePid (PID)");
  EXPECT_THAT(imported.model_text, HasSubstr("period_us: 10000"));  // the outer loop
}

// Issue #26's acceptance: the balancing loop imported from Simulink balances the simulated robot. The robot's model
// (testing/balbot_harness.yaml: apps/balbot/balbot.yaml's sensors, safety stop, motor driver and encoders) references
// the imported controller in place of its own loop; held at 5 degrees until 2 s, as apps/balbot's tests hold it.
TEST(Import, TheImportedBalancingLoopBalancesTheSimulatedRobot) {
  auto folder = TemporaryFolder::make("import_balancing_").value();
  const ImportResult imported = imported_with(
      read_slx_model(parts_of(testing / "tilt_controller_r2022b"), "tilt_controller.slx"), "tilt_controller.m");
  ASSERT_TRUE(imported.problems.empty()) << ::testing::PrintToString(imported.problems);
  std::ofstream{folder.path() / "tilt_controller.yaml"} << imported.model_text;
  std::filesystem::copy_file(testing / "balbot_harness.yaml", folder.path() / "balbot_harness.yaml");
  std::filesystem::copy_file(std::filesystem::path{DUET_SOURCE_DIR} / "apps/balbot/every_second.hpp",
                             folder.path() / "every_second.hpp");  // the robot's Code block
  auto robot_model = model::load_model((folder.path() / "balbot_harness.yaml").string());
  ASSERT_TRUE(robot_model) << robot_model.error();
  const model::ProgramBuild build = model::build_program(robot_model.value());
  for (const model::Diagnostic& diagnostic : build.diagnostics)
    EXPECT_NE(diagnostic.severity, model::Diagnostic::Severity::error) << model::format("harness", diagnostic);
  ASSERT_TRUE(build.program);
  plant::BalbotScenario scenario;
  scenario.initial_tilt_deg = 5;
  scenario.release_time_s = 2;
  const std::unique_ptr<plant::Plant> robot = plant::make_balbot_plant(scenario);
  auto simulated = model::simulate(*build.program, *robot, {.duration_s = 12, .signals = {"stop"}});
  ASSERT_TRUE(simulated) << simulated.error();
  const model::Recording& recording = simulated.value().recording;
  const auto column = [&recording](const std::string& name) {
    const auto found = std::find(recording.names.begin(), recording.names.end(), name);
    EXPECT_NE(found, recording.names.end()) << name;
    return recording.columns[static_cast<std::size_t>(found - recording.names.begin())];
  };
  const std::vector<double> tilt = column("plant.theta_deg");
  const std::vector<double> stopped = column("stop");
  double largest_tilt = 0;
  for (std::size_t row = 0; row < tilt.size(); ++row) {
    if (recording.time_s[row] >= 4) largest_tilt = std::max(largest_tilt, std::abs(tilt[row]));
    if (recording.time_s[row] >= 1.6) {
      EXPECT_EQ(stopped[row], 0.0) << recording.time_s[row];  // never fell
    }
  }
  EXPECT_LT(largest_tilt, 2.5);  // upright, 2 s after the release and on
}

// A packaged text .mdl (R2025b) through the import: its model names no solver, so the base period is given.
TEST(Import, APackagedTextMdlWithTheBasePeriodGiven) {
  auto model = read_simulink_file(testing / "packaged_r2025b.mdl");
  ASSERT_TRUE(model) << model.error();
  const ImportResult without = import_simulink(model.value(), {});
  ASSERT_EQ(without.problems.size(), 1U);
  EXPECT_EQ(without.problems[0],
            "velo_pi: the fixed step is 'not in the file'; give the base period with "
            "--base-period-us");
  const ImportResult imported = import_simulink(model.value(), {.base_period_us = 5000});
  std::unique_ptr<model::Model> keep;
  const auto build = checked(imported, keep);
  ASSERT_TRUE(build);
  Ports plant{{{"inport:speed", 2.5}}};
  ASSERT_TRUE(model::simulate(*build->program, plant, {.duration_s = 0.01, .record_plant = false}));
  EXPECT_EQ(plant.history.at("outport:voltage"), (std::vector<double>{2.0, 2.0, 2.0}));  // 0.8 speed, every 5 ms
}

// The classic .mdl controller (ISO-8859-1, its variables in controller.m, Ts 5 ms) imported and simulated on a tilt
// of 0.001 for six steps, then 0: Verstärkung is K_theta.*scale = 3 (a product, so a literal), the masked Filter's
// alpha 0.9, the Sum |+- their difference e = 2.1 theta, the PI (P 3500, Ki 1000, forward Euler) limited to
// +-Prop.MaxForce = 7.38 with clamping, the Unit Delay a step late from 0; the Logger only ends the tilt.
TEST(Import, TheClassicMdlControllerComputesWhatItsSimulinkBlocksDo) {
  const ImportResult imported = imported_with(read_simulink_file(testing / "controller.mdl"), "controller.m");
  std::unique_ptr<model::Model> keep;
  const auto build = checked(imported, keep);
  ASSERT_TRUE(build);
  EXPECT_THAT(imported.model_text, HasSubstr("base_period_us: 5000\n"));
  EXPECT_EQ(verdict(imported, "balance_controller/Verst\xC3\xA4rkung").what, "Gain k: 3");
  EXPECT_EQ(verdict(imported, "balance_controller/Discrete PID Controller").what, "DiscretePid (PI)");
  EXPECT_THAT(imported.model_text, HasSubstr("  Ki: {value: 1000, "));  // tunable, by its name
  EXPECT_THAT(imported.model_text, HasSubstr("  Prop_MaxForce: {value: 7.38, "));
  Ports plant{
      std::map<std::string, Ports::Inport>{{"inport:theta", [](std::size_t step) { return step < 6 ? 0.001 : 0.0; }},
                                           {"inport:theta_rate", [](std::size_t) { return 0.0; }}}};
  plant.period_s = 0.005;
  ASSERT_TRUE(model::simulate(*build->program, plant, {.duration_s = 0.04, .record_plant = false}));
  // e = 0.0021 while the tilt is 0.001: P e = 7.35, and each step adds Ki Ts e = 0.0105 to the integrator (from 0).
  // Step 3's sum 7.3815 is beyond 7.38: the output is 7.38 and, e pushing further, the integrator stays at 0.0315
  // (clamping) until e is 0 at step 6, where the output is the integrator alone. Torque is the output a step late.
  const std::vector<double> expected{0, 7.35, 7.3605, 7.371, 7.38, 7.38, 7.38, 0.0315, 0.0315};
  const std::vector<double>& torque = plant.history.at("outport:torque");
  ASSERT_EQ(torque.size(), expected.size());
  for (std::size_t step = 0; step < expected.size(); ++step) EXPECT_NEAR(torque[step], expected[step], 1e-12) << step;
}

// Subsystems of each kind, from a classic .mdl: enabled while the gate is positive (outputs held otherwise),
// triggered on the rising edges of the clock, a boolean inport (its count advancing only then), and a function-call
// subsystem that --interrupt makes an interrupt task, fed and read through rate transitions; the interrupt block that
// called it in Simulink is not needed.
TEST(Import, EnabledTriggeredAndFunctionCallSubsystems) {
  auto model = read_simulink_file(testing / "subsystems.mdl");
  ASSERT_TRUE(model) << model.error();
  ImportOptions options;
  options.interrupts["subsystems/ISR"] = {.interrupt = "TIM2", .priority = 3};
  const ImportResult imported = import_simulink(model.value(), options);
  std::unique_ptr<model::Model> keep;
  const auto build = checked(imported, keep);
  ASSERT_TRUE(build);
  EXPECT_EQ(verdict(imported, "subsystems/Timer interrupt").what,
            "raises function calls that --interrupt maps to interrupts: the interrupts stand in for it");
  const std::vector<double> gate{0, 1, 1, 0, 1, 0, 0, 0};
  Ports plant{std::map<std::string, Ports::Inport>{
      {"inport:u", [](std::size_t step) { return 3.0 + static_cast<double>(step); }},
      {"inport:gate", [&gate](std::size_t step) { return gate[step]; }},
      {"inport:clock", [](std::size_t step) { return static_cast<double>(step % 2); }}}};
  plant.interrupt = "TIM2";
  plant.interrupt_steps = {2, 5};
  auto simulated = model::simulate(*build->program, plant, {.duration_s = 0.07, .record_plant = false});
  ASSERT_TRUE(simulated) << simulated.error();
  using Steps = std::vector<double>;
  // 2 u while the gate is open, held while it is shut (0 before it first opens).
  EXPECT_EQ(plant.history.at("outport:gated"), (Steps{0, 8, 10, 10, 14, 14, 14, 14}));
  // The clock rises at steps 1, 3, 5 and 7.
  EXPECT_EQ(plant.history.at("outport:counted"), (Steps{0, 1, 1, 2, 2, 3, 3, 4}));
  // The interrupt comes before its step's base tick: the one at step 2 halves the newest u, step 1's 4; the one at
  // step 5 step 4's 7. The base rate reads the newest half.
  EXPECT_EQ(plant.history.at("outport:halved"), (Steps{0, 0, 2, 2, 2, 3.5, 3.5, 3.5}));
}

TEST(Import, RefusesWhatItCannotProveEqualAndSaysWhereAndWhy) {
  SimulinkModel model = read_slx_model(parts_of(testing / "slx_r2022b"), "pid_loop.slx").value();
  const ImportResult without_variables = import_simulink(model, {});
  ASSERT_FALSE(without_variables.problems.empty());
  EXPECT_EQ(without_variables.problems[0],
            "pid_loop/Discrete PID Controller (PID 1dof): its parameter ControllerParametersSource is not in the "
            "file, and duet knows no default for it");  // a library link's values are all in the file, or it is damaged
  EXPECT_TRUE(without_variables.model_text.empty());
  EXPECT_FALSE(verdict(without_variables, "pid_loop/Discrete PID Controller").imported);
  EXPECT_TRUE(verdict(without_variables, "pid_loop/Limiter/Saturation").imported);
}

// A model m of u -> X -> y, X the block under test.
Block block_x(std::string type, std::map<std::string, std::string> parameters = {}) {
  Block x{.type = std::move(type), .name = "X", .sid = "2", .parameters = std::move(parameters)};
  return x;
}

// A Discrete PID Controller X with the options duet imports, `changed` changed.
Block pid_x(const std::map<std::string, std::string>& changed) {
  std::map<std::string, std::string> parameters{{"SourceType", "PID 1dof"},
                                                {"TimeDomain", "Discrete-time"},
                                                {"Form", "Parallel"},
                                                {"IntegratorMethod", "Forward Euler"},
                                                {"FilterMethod", "Forward Euler"},
                                                {"ControllerParametersSource", "internal"},
                                                {"ExternalReset", "none"},
                                                {"InitialConditionSource", "internal"},
                                                {"TrackingMode", "off"},
                                                {"Controller", "PID"},
                                                {"P", "1"},
                                                {"I", "1"},
                                                {"D", "0.1"},
                                                {"N", "100"},
                                                {"UseFilter", "on"},
                                                {"InitialConditionForIntegrator", "0"},
                                                {"InitialConditionForFilter", "0"},
                                                {"LimitOutput", "on"},
                                                {"UpperSaturationLimit", "1"},
                                                {"LowerSaturationLimit", "-1"},
                                                {"AntiWindupMode", "clamping"},
                                                {"SampleTime", "-1"}};
  for (const auto& [name, value] : changed) parameters[name] = value;
  return block_x("Reference", std::move(parameters));
}

SimulinkModel around(Block x, std::map<std::string, std::string> solver = {{"SolverName", "FixedStepDiscrete"},
                                                                           {"FixedStep", "0.01"}}) {
  SimulinkModel model{.name = "m", .release = "R2022b", .format = "slx (systems/)"};
  model.solver.parameters = std::move(solver);
  model.root.blocks.push_back({.type = "Inport", .name = "u", .sid = "1"});
  model.root.blocks.push_back(std::move(x));
  model.root.blocks.push_back({.type = "Outport", .name = "y", .sid = "3"});
  model.root.lines.push_back({.name = {}, .source = Endpoint{"u", "out", 1}, .destinations = {{"X", "in", 1}}});
  model.root.lines.push_back({.name = {}, .source = Endpoint{"X", "out", 1}, .destinations = {{"y", "in", 1}}});
  return model;
}

// A subsystem X whose contents are an Inport, the given port block and a Gain to an Outport.
Block subsystem_x(Block port_block, std::map<std::string, std::string> parameters = {}) {
  System inside;
  inside.blocks.push_back({.type = "Inport", .name = "in", .sid = "5"});
  inside.blocks.push_back(std::move(port_block));
  inside.blocks.push_back({.type = "Gain", .name = "g", .sid = "7"});
  inside.blocks.push_back({.type = "Outport", .name = "out", .sid = "8"});
  inside.lines.push_back({.name = {}, .source = Endpoint{"in", "out", 1}, .destinations = {{"g", "in", 1}}});
  inside.lines.push_back({.name = {}, .source = Endpoint{"g", "out", 1}, .destinations = {{"out", "in", 1}}});
  Block x = block_x("SubSystem", std::move(parameters));
  x.systems.push_back(std::move(inside));
  return x;
}

// around(x) with u driving x's trigger port too.
SimulinkModel triggered_by_u(Block x) {
  SimulinkModel model = around(std::move(x));
  model.root.lines[0].destinations.push_back({"X", "trigger", 1});
  return model;
}

// What an option means is what counts, not how it is written: initial conditions of 0 written as 0.0 or as a
// variable holding 0, and a P or PD controller's integrator method (it has no integrator).
TEST(Import, APidsOptionsCountByTheirMeaning) {
  ImportOptions options;
  options.variables["x0"] = Value::scalar(0);
  const ImportResult written_otherwise = import_simulink(
      around(pid_x({{"InitialConditionForIntegrator", "0.0"}, {"InitialConditionForFilter", "x0"}})), options);
  EXPECT_TRUE(written_otherwise.problems.empty()) << ::testing::PrintToString(written_otherwise.problems);
  const ImportResult without_integrator =
      import_simulink(around(pid_x({{"Controller", "PD"}, {"IntegratorMethod", "Backward Euler"}})), {});
  EXPECT_TRUE(without_integrator.problems.empty()) << ::testing::PrintToString(without_integrator.problems);
  EXPECT_EQ(verdict(without_integrator, "m/X").what, "DiscretePid (PD)");
}

struct Unsupported {
  std::string label;
  SimulinkModel model;
  std::string message;
};

class ImportRefuses : public ::testing::TestWithParam<Unsupported> {};

TEST_P(ImportRefuses, WithThePathAndTheReason) {
  const ImportResult result = import_simulink(GetParam().model, {});
  ASSERT_EQ(result.problems.size(), 1U) << ::testing::PrintToString(result.problems);
  EXPECT_EQ(result.problems[0], GetParam().message);
  EXPECT_TRUE(result.model_text.empty());
}

const std::string discrete_only = "a continuous block: duet imports discrete models only (discretise it in Simulink)";

INSTANTIATE_TEST_SUITE_P(
    Variants, ImportRefuses,
    ::testing::Values(
        Unsupported{"continuous", around(block_x("Integrator")), "m/X (Integrator): " + discrete_only},
        Unsupported{"s_function", around(block_x("S-Function")),
                    "m/X (S-Function): an S-Function: its code is not in the model"},
        Unsupported{
            "matlab_function",
            around(subsystem_x({.type = "Gain", .name = "k", .sid = "6"}, {{"SFBlockType", "MATLAB Function"}})),
            "m/X (SubSystem): a MATLAB Function block: its code is MATLAB or Stateflow, which duet does not "
            "translate"},
        Unsupported{"chart", around(subsystem_x({.type = "Gain", .name = "k", .sid = "6"}, {{"SFBlockType", "Chart"}})),
                    "m/X (SubSystem): a Chart block: its code is MATLAB or Stateflow, which duet does not translate"},
        Unsupported{"unknown_type", around(block_x("Fcn")),
                    "m/X (Fcn): no duet block has the semantics of a Fcn block (docs/IMPORT.md lists the ones it has)"},
        Unsupported{"unknown_link",
                    around(block_x("Reference", {{"SourceType", "Counter Free-Running"},
                                                 {"SourceBlock", "simulink/Sources/Counter\nFree-Running"}})),
                    "m/X (Counter Free-Running): a link to the library block 'simulink/Sources/Counter\nFree-Running' "
                    "(Counter Free-Running), which duet has no implementation of (docs/IMPORT.md lists the ones it "
                    "has)"},
        Unsupported{"matrix_gain", around(block_x("Gain", {{"Multiplication", "Matrix(u*K)"}})),
                    "m/X (Gain): Multiplication 'Matrix(u*K)': duet multiplies element-wise or K*u (Matrix(K*u))"},
        Unsupported{"gain_type", around(block_x("Gain", {{"ParamDataTypeStr", "single"}})),
                    "m/X (Gain): ParamDataTypeStr 'single': duet's Gain keeps k in its input's type"},
        Unsupported{"sine", around(block_x("Trigonometry")),
                    "m/X (Trigonometry): Operator sin: of the trigonometric functions duet has atan2"},
        Unsupported{"output_type", around(block_x("Gain", {{"OutDataTypeStr", "single"}})),
                    "m/X (Gain): OutDataTypeStr 'single': duet's Gain computes in its input's type (convert with a "
                    "DataTypeConversion block)"},
        Unsupported{"unresolved", around(block_x("Gain", {{"Gain", "Kx"}})),
                    "m/X (Gain): Gain 'Kx': column 1: unresolved name 'Kx'"},
        Unsupported{"continuous_time", around(block_x("UnitDelay", {{"SampleTime", "0"}})),
                    "m/X (UnitDelay): SampleTime '0' is continuous (0): duet imports discrete models only"},
        Unsupported{"offset", around(block_x("UnitDelay", {{"SampleTime", "[0.01 0.005]"}})),
                    "m/X (UnitDelay): SampleTime '[0.01 0.005]' has an offset, which duet's rates do not"},
        Unsupported{"no_multiple", around(block_x("UnitDelay", {{"SampleTime", "0.015"}})),
                    "m/X (UnitDelay): SampleTime 0.015 s is not a whole multiple of the base period of 10000 us"},
        Unsupported{"backward_euler",
                    around(block_x("DiscreteIntegrator", {{"IntegratorMethod", "Integration: Backward Euler"}})),
                    "m/X (DiscreteIntegrator): IntegratorMethod is 'Integration: Backward Euler': duet's "
                    "DiscreteIntegrator integrates by forward Euler only"},
        Unsupported{"one_input_sum", around(block_x("Sum", {{"Inputs", "+"}})),
                    "m/X (Sum): one input (Inputs '+') combines its elements, which duet's Sum does not: use two "
                    "inputs or a Mux"},
        Unsupported{"huge_count", around(block_x("Sum", {{"Inputs", "2e26"}})),
                    "m/X (Sum): Inputs '2e26' is not a whole number from 1 to 64"},
        Unsupported{"commented", around(block_x("Gain", {{"Commented", "on"}})),
                    "m/X (Gain): commented out (on): refused, uncomment or delete it"},
        Unsupported{"logic_of_uint8", around(block_x("RelationalOperator", {{"OutDataTypeStr", "uint8"}})),
                    "m/X (RelationalOperator): OutDataTypeStr 'uint8': duet's logic blocks output booleans (set it "
                    "to boolean, or convert after it with a DataTypeConversion block)"},
        Unsupported{"nxor", around(block_x("Logic", {{"Operator", "NXOR"}})),
                    "m/X (Logic): Operator NXOR is not one of duet's Logic (AND, OR, XOR, NAND, NOR, NOT)"},
        Unsupported{"one_input_logic", around(block_x("Logic", {{"Operator", "OR"}, {"Inputs", "1"}})),
                    "m/X (Logic): one input applies OR across its elements, which duet's Logic does not: use two "
                    "inputs or more"},
        Unsupported{"matrix_division", around(block_x("Product", {{"Multiplication", "Matrix(*)"}, {"Inputs", "*/"}})),
                    "m/X (Product): Inputs '*/' with Matrix(*): duet's matrix product is of two inputs (**), without "
                    "inverses"},
        Unsupported{"newton_raphson_reciprocal",
                    around(block_x("Math", {{"Operator", "reciprocal"}, {"AlgorithmType", "Newton-Raphson"}})),
                    "m/X (Math): AlgorithmType is 'Newton-Raphson': duet's reciprocal is the exact division 1/u"},
        Unsupported{"lookup_table_object",
                    around(block_x("Lookup_n-D",
                                   {{"NumberOfTableDimensions", "1"}, {"DataSpecification", "Lookup table object"}})),
                    "m/X (Lookup_n-D): DataSpecification is 'Lookup table object': the table and breakpoints must "
                    "be the block's own, not a lookup table object's"},
        Unsupported{"table_from_port",
                    around(block_x("Lookup_n-D", {{"NumberOfTableDimensions", "1"}, {"TableSource", "Input port"}})),
                    "m/X (Lookup_n-D): TableSource is 'Input port': a table or breakpoints from input ports are not "
                    "duet's Interpolation's"},
        Unsupported{"inherited_conversion", around(block_x("DataTypeConversion")),
                    "m/X (DataTypeConversion): OutDataTypeStr 'Inherit: Inherit via back propagation': duet's "
                    "Convert needs the output type written out (double, single, int8 ... uint32, boolean)"},
        Unsupported{"two_dimensional_table", around(block_x("Lookup_n-D")),
                    "m/X (Lookup_n-D): NumberOfTableDimensions is '2': duet's Interpolation has one dimension"},
        Unsupported{"delay_reset", around(block_x("Delay", {{"ExternalReset", "Rising"}})),
                    "m/X (Delay): ExternalReset is 'Rising': a delay with an external reset is not imported"},
        Unsupported{"transfer_function_state", around(block_x("DiscreteTransferFcn", {{"InitialStates", "1"}})),
                    "m/X (DiscreteTransferFcn): InitialStates 1: duet's TransferFunction starts at rest"},
        Unsupported{"pid_ideal",
                    around(block_x("Reference",
                                   {{"SourceType", "PID 1dof"}, {"TimeDomain", "Discrete-time"}, {"Form", "Ideal"}})),
                    "m/X (PID 1dof): Form is 'Ideal': duet's DiscretePid is the parallel form"},
        Unsupported{"pid_controller", around(pid_x({{"Controller", "PIDF"}})),
                    "m/X (PID 1dof): Controller 'PIDF' is not one of P, I, PI, PD, PID"},
        Unsupported{"pid_unfiltered", around(pid_x({{"UseFilter", "off"}})),
                    "m/X (PID 1dof): UseFilter is 'off': duet's derivative is always filtered"},
        Unsupported{"pid_integrator_initial", around(pid_x({{"InitialConditionForIntegrator", "1"}})),
                    "m/X (PID 1dof): InitialConditionForIntegrator is 1: duet's integrator starts at 0"},
        Unsupported{"pid_back_calculation", around(pid_x({{"AntiWindupMode", "back-calculation"}})),
                    "m/X (PID 1dof): AntiWindupMode back-calculation: duet's DiscretePid clamps or does nothing"},
        Unsupported{"pid_typed", around(pid_x({{"SumOutDataTypeStr", "single"}})),
                    "m/X (PID 1dof): SumOutDataTypeStr 'single': duet's DiscretePid computes in its input's type "
                    "throughout"},
        Unsupported{"pid_external_sample_time", around(pid_x({{"UseExternalTs", "on"}})),
                    "m/X (PID 1dof): UseExternalTs is 'on': a sample time from a port is not imported"},
        Unsupported{"pid_i_times_ts", around(pid_x({{"UseKiTs", "on"}})),
                    "m/X (PID 1dof): UseKiTs is 'on': the integral gain given as I*Ts is not imported"},
        Unsupported{"pid_integrator_limits", around(pid_x({{"LimitIntegrator", "on"}})),
                    "m/X (PID 1dof): LimitIntegrator is 'on': duet's DiscretePid does not limit its integrator"},
        Unsupported{"pid_external_derivative", around(pid_x({{"UseExternalDerivativeSource", "on"}})),
                    "m/X (PID 1dof): UseExternalDerivativeSource is 'on': a derivative from a port is not imported"},
        Unsupported{"pid_external_limits", around(pid_x({{"SatLimitsSource", "external"}})),
                    "m/X (PID 1dof): SatLimitsSource is 'external': output limits from ports are not imported"},
        Unsupported{
            "conversion_wraps",
            around(block_x("DataTypeConversion", {{"OutDataTypeStr", "int8"}, {"SaturateOnIntegerOverflow", "off"}})),
            "m/X (DataTypeConversion): SaturateOnIntegerOverflow is 'off': duet's Convert saturates"},
        Unsupported{"conversion_rounds_to_nearest",
                    around(block_x("DataTypeConversion", {{"OutDataTypeStr", "uint8"}, {"RndMeth", "Nearest"}})),
                    "m/X (DataTypeConversion): RndMeth is 'Nearest': duet's Convert rounds toward zero"},
        Unsupported{"conversion_sample_time",
                    around(block_x("DataTypeConversion", {{"OutDataTypeStr", "single"}, {"SampleTime", "0.015"}})),
                    "m/X (DataTypeConversion): SampleTime 0.015 s is not a whole multiple of the base period of "
                    "10000 us"},
        Unsupported{"global_goto", around(block_x("Goto", {{"TagVisibility", "global"}})),
                    "m/X (Goto): a scoped or global tag: refused, use lines or local tags"},
        Unsupported{"single_tasking_rate_transition",
                    around(block_x("RateTransition"),
                           {{"SolverName", "FixedStepDiscrete"}, {"FixedStep", "0.01"}, {"EnableMultiTasking", "off"}}),
                    "m/X (RateTransition): the model runs single-tasking, where a rate transition passes its value "
                    "on at once; duet's rate transitions are those of multitasking (set the solver's tasking mode to "
                    "multitasking)"},
        Unsupported{
            "function_call_unmapped",
            around(subsystem_x(
                {.type = "TriggerPort", .name = "f", .sid = "6", .parameters = {{"TriggerType", "function-call"}}})),
            "m/X (SubSystem): a function-call subsystem: map it to an interrupt with --interrupt "
            "'m/X=IRQ:PRIORITY'"},
        Unsupported{"trigger_compatibility", around(subsystem_x({.type = "TriggerPort", .name = "t", .sid = "6"})),
                    "m/X (SubSystem): its trigger's InitialTriggerSignalState is not 'zero': duet's edge detection "
                    "starts from zero (set it to zero in Simulink)"},
        Unsupported{"trigger_of_doubles",
                    triggered_by_u(subsystem_x({.type = "TriggerPort",
                                                .name = "t",
                                                .sid = "6",
                                                .parameters = {{"InitialTriggerSignalState", "zero"}}})),
                    "m/X (SubSystem): its trigger signal u (from u, Inport) may be negative, and then Simulink's "
                    "edges and duet's differ (Simulink also triggers on a rise from below zero to exactly zero); "
                    "trigger with a boolean or unsigned signal (a Compare To Zero, a Relational Operator, an Inport "
                    "of type boolean) so that both agree"},
        Unsupported{
            "enable_reset",
            around(subsystem_x(
                {.type = "EnablePort", .name = "e", .sid = "6", .parameters = {{"StatesWhenEnabling", "reset"}}})),
            "m/X (SubSystem): its enable port resets states or shows an output, which duet's enabled "
            "subsystems do not"},
        Unsupported{"unconnected", around(block_x("Sum", {{"Inputs", "+++"}})),
                    "m/X (Sum): its input 2 is not connected"},
        Unsupported{"variable_step", around(block_x("Gain"), {{"SolverName", "ode45"}}),
                    "m: the solver ode45 is variable-step; duet runs fixed-step discrete models (set a fixed-step "
                    "solver in Simulink)"},
        Unsupported{"auto_step", around(block_x("Gain"), {{"SolverName", "FixedStepAuto"}, {"FixedStep", "auto"}}),
                    "m: the fixed step is 'auto'; give the base period with --base-period-us"},
        Unsupported{"no_solver", around(block_x("Gain"), {}),
                    "m: the fixed step is 'not in the file'; give the base period with --base-period-us"}),
    [](const ::testing::TestParamInfo<Unsupported>& variant) { return variant.param.label; });

// A root inport of a declared type converts what the plant hands (doubles) to it; the blocks after compute in it.
TEST(Import, ARootInportOfADeclaredTypeConvertsThePlantsValue) {
  SimulinkModel model = around(block_x("Gain", {{"Gain", "2"}}));
  model.root.blocks[0].parameters["OutDataTypeStr"] = "single";
  const ImportResult imported = import_simulink(model, {});
  std::unique_ptr<model::Model> keep;
  const auto build = checked(imported, keep);
  ASSERT_TRUE(build);
  EXPECT_THAT(imported.model_text, HasSubstr("type: Convert\n    parameters: {type: single}\n    inputs: {u: u_read}"));
  Ports plant{{{"inport:u", 0.1}}};
  ASSERT_TRUE(model::simulate(*build->program, plant, {.duration_s = 0, .record_plant = false}));
  EXPECT_EQ(plant.written.at("outport:y"), static_cast<double>(2.0F * 0.1F));  // in single, not 0.2
}

// An algebraic loop imports (each block is fine) but the model does not check: duet says where the loop is.
TEST(Import, AnAlgebraicLoopIsFoundWhenTheModelIsChecked) {
  SimulinkModel model = around(block_x("Sum", {{"Inputs", "++"}}));
  model.root.lines[1].destinations.push_back({"X", "in", 2});  // X's output back into its second input
  const ImportResult result = import_simulink(model, {});
  ASSERT_TRUE(result.problems.empty()) << ::testing::PrintToString(result.problems);
  auto parsed = model::parse_model(result.model_text, "m.yaml");
  ASSERT_TRUE(parsed) << parsed.error();
  const model::ProgramBuild build = model::build_program(parsed.value());
  ASSERT_FALSE(build.program);
  ASSERT_FALSE(build.diagnostics.empty());
  EXPECT_THAT(model::format("m.yaml", build.diagnostics.front()), HasSubstr("algebraic loop")) << result.model_text;
}

// u converted to `type`, then X: a Sum of it and itself (its SaturateOnIntegerOverflow as given), in a file of
// `release`; the problems integer_problems finds in the checked model.
std::vector<std::string> integer_problems_of_sum(const std::string& type, const std::string& release,
                                                 std::map<std::string, std::string> sum_parameters) {
  sum_parameters["Inputs"] = "++";
  SimulinkModel model = around(block_x("Sum", std::move(sum_parameters)));
  model.release = release;
  model.root.blocks.push_back({.type = "DataTypeConversion",
                               .name = "c",
                               .sid = "4",
                               .parameters = {{"OutDataTypeStr", type}, {"RndMeth", "Zero"}}});
  model.root.lines[0].destinations = {{"c", "in", 1}};
  model.root.lines.push_back({.name = {}, .source = Endpoint{"c", "out", 1}, .destinations = {{"X", "in", 1}}});
  model.root.lines.back().destinations.push_back({"X", "in", 2});
  const ImportResult result = import_simulink(model, {});
  EXPECT_TRUE(result.problems.empty()) << ::testing::PrintToString(result.problems);
  auto parsed = model::parse_model(result.model_text, "m.yaml");
  EXPECT_TRUE(parsed) << (parsed ? "" : parsed.error());
  if (!parsed) return {"not parsed"};
  const model::ProgramBuild build = model::build_program(parsed.value());
  EXPECT_TRUE(build.program) << result.model_text;
  if (!build.program) return {"not checked"};
  return integer_problems(result, output_type_in(*build.program));
}

// Simulink saturates an integer overflow where SaturateOnIntegerOverflow is on (the default before R2020a); duet's
// Sum wraps. The import cannot see types; once the model is checked, a Sum that computes in integers is refused.
TEST(Import, ASumThatSaturatesIntegersIsRefusedOnceTheCheckedModelShowsItsType) {
  EXPECT_EQ(integer_problems_of_sum("int16", "R2019b", {}),
            std::vector<std::string>{"m/X (Sum): it computes in int16: Simulink saturates an integer overflow "
                                     "(SaturateOnIntegerOverflow on), duet's Sum wraps (set it off in Simulink, or "
                                     "compute in floating point)"});
  EXPECT_EQ(integer_problems_of_sum("int16", "R2019b", {{"SaturateOnIntegerOverflow", "off"}}),
            std::vector<std::string>{});                                                  // both wrap
  EXPECT_EQ(integer_problems_of_sum("int16", "R2022b", {}), std::vector<std::string>{});  // off by default since R2020a
  EXPECT_EQ(integer_problems_of_sum("single", "R2019b", {}), std::vector<std::string>{});  // no overflow to saturate
}

}  // namespace
}  // namespace duet::simulink_import
