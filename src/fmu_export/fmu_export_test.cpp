#include "duet/fmu_export/fmu_export.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "duet/fmi/archive.hpp"
#include "duet/fmi/imported_fmu.hpp"
#include "duet/fmi/model_description_reader.hpp"
#include "duet/fmu_export/fmu_interface.hpp"
#include "duet/model/model_file.hpp"
#include "duet/support/temporary_folder.hpp"
#include "duet/support/text_file.hpp"

namespace duet::fmu_export {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::MatchesRegex;

const std::string thermostat = DUET_SOURCE_DIR "/apps/thermostat/thermostat.yaml";
const std::string heater = DUET_SOURCE_DIR "/apps/thermostat/heater.yaml";
const std::string pulses = DUET_SOURCE_DIR "/src/fmu_export/testing/pulses.yaml";

struct Loaded {
  std::unique_ptr<model::Model> model;
  model::Program program;
};

Loaded load(const std::string& file) {
  auto model = std::make_unique<model::Model>(model::load_model(file).value());
  model::ProgramBuild build = model::build_program(*model);
  return {std::move(model), std::move(*build.program)};
}

std::filesystem::path exported(const std::string& model_file, fmi::FmiVersion version,
                               const std::filesystem::path& folder) {
  const Loaded loaded = load(model_file);
  const std::filesystem::path fmu =
      folder / (loaded.program.model->name + (version == fmi::FmiVersion::v3 ? "_fmi3.fmu" : "_fmi2.fmu"));
  auto summary = export_fmu(loaded.program, model_file, fmu, version);
  EXPECT_TRUE(summary.ok()) << (summary.ok() ? "" : summary.error());
  return fmu;
}

std::vector<std::string> entry_names(const fmi::Archive& archive) {
  std::vector<std::string> names;
  for (const fmi::ArchiveEntry& entry : archive.entries()) names.push_back(entry.name);
  std::sort(names.begin(), names.end());
  return names;
}

const fmi::Variable& variable(const fmi::ModelDescription& description, const std::string& name) {
  const auto found = std::find_if(description.variables.begin(), description.variables.end(),
                                  [&name](const fmi::Variable& v) { return v.name == name; });
  EXPECT_NE(found, description.variables.end()) << name;
  return *found;
}

TEST(FmuExport, TheThermostatAsAnFmi3FmuDescribesItsResourcesParametersAndSignals) {
  auto folder = TemporaryFolder::make("fmu_export_test_").value();
  auto archive = fmi::Archive::open(exported(thermostat, fmi::FmiVersion::v3, folder.path())).value();
  EXPECT_THAT(entry_names(archive), ElementsAre("binaries/x86_64-linux/thermostat.so", "modelDescription.xml"));
  const fmi::ModelDescription description =
      fmi::read_model_description(archive.read("modelDescription.xml").value()).value();
  EXPECT_EQ(description.version, fmi::FmiVersion::v3);
  EXPECT_EQ(description.model_name, "thermostat");
  EXPECT_THAT(description.token, MatchesRegex("\\{duet-thermostat-[0-9a-f]{16}\\}"));
  EXPECT_EQ(description.co_simulation.model_identifier, "thermostat");
  EXPECT_TRUE(description.co_simulation.can_handle_variable_communication_step_size);
  EXPECT_EQ(description.co_simulation.fixed_internal_step_size, 0.01);
  EXPECT_EQ(description.default_experiment->step_size, 0.01);

  std::vector<std::string> names;
  for (const fmi::Variable& v : description.variables) names.push_back(v.name);
  EXPECT_THAT(names, ElementsAre("time", "adc:ADC1/6", "gpio:LED0", "setpoint", "sample", "heating"));
  EXPECT_EQ(variable(description, "time").causality, fmi::Causality::independent);
  const fmi::Variable& adc = variable(description, "adc:ADC1/6");
  EXPECT_EQ(adc.causality, fmi::Causality::input);
  EXPECT_EQ(adc.type, fmi::VariableType::float64);
  EXPECT_EQ(adc.start, "0");
  EXPECT_THAT(adc.description, HasSubstr("read by adc (AdcDma)"));
  EXPECT_EQ(variable(description, "gpio:LED0").causality, fmi::Causality::output);
  const fmi::Variable& setpoint = variable(description, "setpoint");
  EXPECT_EQ(setpoint.causality, fmi::Causality::parameter);
  EXPECT_EQ(setpoint.variability, fmi::Variability::tunable);  // the step's Compare reads it
  EXPECT_EQ(setpoint.type, fmi::VariableType::uint16);
  EXPECT_EQ(setpoint.start, "2000");
  EXPECT_EQ(variable(description, "heating").type, fmi::VariableType::boolean);
  EXPECT_EQ(variable(description, "sample").causality, fmi::Causality::local);
  ASSERT_EQ(description.outputs.size(), 1U);
  EXPECT_EQ(description.variables[description.outputs[0]].name, "gpio:LED0");
  for (std::size_t k = 0; k < description.variables.size(); ++k) EXPECT_EQ(description.variables[k].value_reference, k);
}

TEST(FmuExport, TheHeaterAsAnFmi2FmuUsesTwoPointZerosTypesAndPlatform) {
  auto folder = TemporaryFolder::make("fmu_export_test_").value();
  auto archive = fmi::Archive::open(exported(heater, fmi::FmiVersion::v2, folder.path())).value();
  EXPECT_THAT(entry_names(archive), ElementsAre("binaries/linux64/heater.so", "modelDescription.xml"));
  const fmi::ModelDescription description =
      fmi::read_model_description(archive.read("modelDescription.xml").value()).value();
  EXPECT_EQ(description.version, fmi::FmiVersion::v2);
  EXPECT_FALSE(description.co_simulation.fixed_internal_step_size.has_value());
  EXPECT_EQ(variable(description, "gpio:LED0").causality, fmi::Causality::input);    // PlantInput
  EXPECT_EQ(variable(description, "adc:ADC1/6").causality, fmi::Causality::output);  // PlantOutput
  const fmi::Variable& temperature = variable(description, "temperature");
  EXPECT_EQ(temperature.type, fmi::VariableType::real);
  EXPECT_EQ(temperature.unit, "degC");
  EXPECT_THAT(description.units, ElementsAre("s", "degC"));
}

// A model's Inports and Outports on its own are resources of its own names: the FMU's inputs and outputs.
TEST(FmuExport, AModelsInportsAndOutportsAreItsInputsAndOutputs) {
  const Loaded loaded = load(DUET_SOURCE_DIR "/apps/tilt_reference/tilt_controller.yaml");
  const fmi::ModelDescription description = fmu_interface(loaded.program, fmi::FmiVersion::v3).description;
  EXPECT_EQ(variable(description, "inport:theta").causality, fmi::Causality::input);
  EXPECT_EQ(variable(description, "inport:setpoint").causality, fmi::Causality::input);
  EXPECT_THAT(variable(description, "inport:theta").description, HasSubstr("read by theta (Inport)"));
  ASSERT_EQ(description.outputs.size(), 1U);
  EXPECT_EQ(description.variables[description.outputs[0]].name, "outport:duty");
}

TEST(FmuExport, WithoutACompilerItSaysWhichItLookedFor) {
  auto folder = TemporaryFolder::make("fmu_export_test_").value();
  const Loaded loaded = load(heater);
  const char* before = std::getenv("CXX");
  const std::string kept = before == nullptr ? "" : before;
  setenv("CXX", "/nonexistent/c++", 1);
  auto summary = export_fmu(loaded.program, heater, folder.path() / "heater.fmu", fmi::FmiVersion::v3);
  if (before == nullptr) {
    unsetenv("CXX");
  } else {
    setenv("CXX", kept.c_str(), 1);
  }
  ASSERT_FALSE(summary.ok());
  EXPECT_EQ(summary.error(), "the C++ compiler '/nonexistent/c++' was not found (set CXX)");
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "heater.fmu"));
}

// The thermostat and its heater, exported, in a closed loop driven by an FMI host written in C, step by step equal to
// `duet sim thermostat.yaml --plant heater.yaml` (testing/c_host.c says what else it checks).
void drive_with_the_c_host(fmi::FmiVersion version) {
  auto folder = TemporaryFolder::make("fmu_export_test_").value();
  const auto unpack = [&](const std::string& model_file) {
    auto archive = fmi::Archive::open(exported(model_file, version, folder.path())).value();
    auto description = fmi::read_model_description(archive.read("modelDescription.xml").value()).value();
    return std::pair{std::move(archive).extract().value(), std::move(description)};
  };
  const auto [controller_folder, controller] = unpack(thermostat);
  const auto [plant_folder, plant] = unpack(heater);
  const std::string platform = version == fmi::FmiVersion::v3 ? "x86_64-linux" : "linux64";
  const std::filesystem::path csv = folder.path() / "sim.csv";
  const std::string sim = std::string{DUET_PROGRAM} + " sim '" + thermostat + "' --plant '" + heater +
                          "' --duration 3 --csv '" + csv.string() + "' --no-plot > /dev/null";
  ASSERT_EQ(std::system(sim.c_str()), 0) << sim;
  const auto reference = [](const fmi::ModelDescription& description, const std::string& name) {
    return " " + std::to_string(variable(description, name).value_reference);
  };
  const std::string host =
      std::string{DUET_FMU_C_HOST} + (version == fmi::FmiVersion::v3 ? " 3 '" : " 2 '") +
      (controller_folder.path() / "binaries" / platform / "thermostat.so").string() + "' '" + controller.token + "' '" +
      (plant_folder.path() / "binaries" / platform / "heater.so").string() + "' '" + plant.token + "' '" +
      csv.string() + "' 300" + reference(controller, "adc:ADC1/6") + reference(controller, "gpio:LED0") +
      reference(controller, "setpoint") + reference(controller, "heating") + reference(controller, "sample") +
      reference(plant, "gpio:LED0") + reference(plant, "adc:ADC1/6") + " > '" + (folder.path() / "host.txt").string() +
      "'";
  const int status = std::system(host.c_str());
  const auto output = read_text_file((folder.path() / "host.txt").string());
  const std::string text = output.ok() ? output.value() : "(no output: " + output.error() + ")";
  EXPECT_EQ(status, 0) << text;
  EXPECT_THAT(text, HasSubstr("passed: 0 failed checks"));
}

TEST(FmuExport, AnFmi3FmuDrivenByAnIndependentCHostFollowsTheRulesAndDuetSim) {
  drive_with_the_c_host(fmi::FmiVersion::v3);
}

TEST(FmuExport, AnFmi2FmuDrivenByAnIndependentCHostFollowsTheRulesAndDuetSim) {
  drive_with_the_c_host(fmi::FmiVersion::v2);
}

// An interrupt task runs when the importer counts its interrupt up: as often as the count grew, at the start of the
// next step, interrupts raised together most urgent first (TIM2, priority 3, before EXTI0, priority 5: the pin they
// both drive shows EXTI0's low). A count that goes back or grows beyond 1000 in a step is refused, running nothing.
void raise_interrupts(fmi::FmiVersion version) {
  auto folder = TemporaryFolder::make("fmu_export_test_").value();
  const std::filesystem::path file = exported(pulses, version, folder.path());
  auto opened = fmi::ImportedFmu::open(file, {});
  ASSERT_TRUE(opened.ok()) << opened.error();
  fmi::ImportedFmu& fmu = *opened.value();
  ASSERT_TRUE(fmu.initialize(0, 0.001, [] { return done(); }).ok());
  const auto value = [&fmu](const std::string& name) { return fmu.get(*fmu.variable(name)).value(); };
  const auto raise = [&fmu](const std::string& interrupt, double count) {
    ASSERT_TRUE(fmu.set(*fmu.variable("interrupt:" + interrupt), count).ok());
  };
  ASSERT_TRUE(fmu.advance_to(0.002).ok());
  EXPECT_EQ(value("ticks"), 3);  // the periodic task runs alone
  EXPECT_EQ(value("pulses"), 0);
  EXPECT_EQ(value("timer_events"), 0);
  raise("EXTI0", 3);
  ASSERT_TRUE(fmu.advance_to(0.003).ok());
  EXPECT_EQ(value("pulses"), 3);
  EXPECT_EQ(value("gpio:LED0"), 0);
  raise("EXTI0", 4);
  raise("TIM2", 1);
  ASSERT_TRUE(fmu.advance_to(0.004).ok());
  EXPECT_EQ(value("pulses"), 4);
  EXPECT_EQ(value("timer_events"), 1);
  EXPECT_EQ(value("gpio:LED0"), 0);  // TIM2 first, then EXTI0
  ASSERT_TRUE(fmu.advance_to(0.005).ok());
  EXPECT_EQ(value("pulses"), 4);  // nothing raised since
  EXPECT_EQ(value("ticks"), 6);
  raise("TIM2", 1002);
  const Status runaway = fmu.advance_to(0.006);
  ASSERT_FALSE(runaway.ok());
  EXPECT_THAT(runaway.error(), HasSubstr("interrupt:TIM2 grew by 1001 in one step; at most 1000 interrupts of one "
                                         "kind run in a step"));

  auto again = fmi::ImportedFmu::open(file, {});
  ASSERT_TRUE(again.ok()) << again.error();
  ASSERT_TRUE(again.value()->initialize(0, 0.001, [] { return done(); }).ok());
  ASSERT_TRUE(again.value()->set(*again.value()->variable("interrupt:EXTI0"), 2).ok());
  ASSERT_TRUE(again.value()->advance_to(0.001).ok());
  ASSERT_TRUE(again.value()->set(*again.value()->variable("interrupt:EXTI0"), 1).ok());
  const Status back = again.value()->advance_to(0.002);
  ASSERT_FALSE(back.ok());
  EXPECT_THAT(back.error(), HasSubstr("interrupt:EXTI0 went back from 2 to 1: it counts the interrupts raised"));
}

TEST(FmuExport, AnFmi3FmuRunsAnInterruptTaskWhenTheImporterCountsItsInterruptUp) {
  raise_interrupts(fmi::FmiVersion::v3);
}

TEST(FmuExport, AnFmi2FmuRunsAnInterruptTaskWhenTheImporterCountsItsInterruptUp) {
  raise_interrupts(fmi::FmiVersion::v2);
}

}  // namespace
}  // namespace duet::fmu_export
