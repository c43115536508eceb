// The import of the hand-written test models: what each block becomes, the model duet checks and simulates, values
// against what Simulink's blocks compute by their documentation, and refusals with the block's path and reason.
#include "duet/simulink_import/import.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/plant.hpp"
#include "duet/simulink_import/simulink_file.hpp"
#include "duet/simulink_import/slx_model.hpp"
#include "duet/support/text_file.hpp"
#include "testing/package_folder.hpp"

namespace duet::simulink_import {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path testing = DUET_SIMULINK_TESTING_DIR;

// A plant that answers the imported model's root inports with fixed values and keeps what its outports write.
class Ports : public plant::Plant {
 public:
  explicit Ports(std::map<std::string, double> inports) : inports_(std::move(inports)) {}
  void advance(double, const plant::RaiseInterrupt&) override {}
  void write(std::string_view resource, std::span<const double> values) override {
    written[std::string{resource}] = values[0];
  }
  void read(std::string_view resource, std::span<double> values) override {
    values[0] = inports_.at(std::string{resource});
  }
  std::map<std::string, double> written;

 private:
  std::map<std::string, double> inports_;
};

const Verdict& verdict(const ImportResult& result, const std::string& path) {
  for (const Verdict& each : result.report)
    if (each.path == path) return each;
  ADD_FAILURE() << "no verdict for " << path;
  static const Verdict none;
  return none;
}

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
  EXPECT_EQ(verdict(imported, "tilt_loop/theta").what, "PlantInput inport:theta");

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

TEST(Import, RefusesWhatItCannotProveEqualAndSaysWhereAndWhy) {
  SimulinkModel model = read_slx_model(parts_of(testing / "slx_r2022b"), "pid_loop.slx").value();
  const ImportResult without_variables = import_simulink(model, {});
  ASSERT_FALSE(without_variables.problems.empty());
  EXPECT_EQ(without_variables.problems[0],
            "pid_loop/Discrete PID Controller (PID 1dof): its parameter IntegratorMethod is not in the file, and "
            "duet knows no default for it");  // a library link's values are all in the file, or it is damaged
  EXPECT_TRUE(without_variables.model_text.empty());
  EXPECT_FALSE(verdict(without_variables, "pid_loop/Discrete PID Controller").imported);
  EXPECT_TRUE(verdict(without_variables, "pid_loop/Limiter/Saturation").imported);
}

}  // namespace
}  // namespace duet::simulink_import
