// The mapping file: read, and checked against the first-order lag FMU's description, every problem with its place.
#include "duet/fmu_plant/fmu_mapping.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "duet/fmi/archive.hpp"
#include "duet/fmi/fmu_contents.hpp"
#include "duet/support/temporary_folder.hpp"

namespace duet::fmu_plant {
namespace {

fmi::ModelDescription lag_description() {
  const std::filesystem::path file = std::filesystem::path{DUET_TEST_FMU_DIR} / "FirstOrderLag_fmi3.fmu";
  return fmi::read_description(fmi::Archive::open(file).value(), file).value();
}

class MappingTest : public ::testing::Test {
 protected:
  std::string write(const std::string& text) {
    const std::string file = (folder_.path() / "m.yaml").string();
    std::ofstream{file} << text;
    return file;
  }
  // The message a mapping gets, reading or checking, without the file's name.
  std::string problem(const std::string& text) {
    const std::string file = write(text);
    auto mapping = read_fmu_mapping(file);
    std::string message;
    if (!mapping) {
      message = mapping.error();
    } else if (auto checked = check_fmu_mapping(mapping.value(), lag_description()); !checked) {
      message = checked.error();
    }
    return message.starts_with(file) ? "M" + message.substr(file.size()) : message;
  }

 private:
  TemporaryFolder folder_ = TemporaryFolder::make("duet-mapping-test-").value();
};

TEST_F(MappingTest, ReadsConnectionsSettingsAndObservedVariables) {
  auto mapping = read_fmu_mapping(DUET_FMU_PLANT_TESTING_DIR "/lag.connect.yaml");
  ASSERT_TRUE(mapping) << mapping.error();
  ASSERT_EQ(mapping.value().inputs.size(), 1u);
  EXPECT_EQ(mapping.value().inputs[0].variable, "u");
  EXPECT_EQ(mapping.value().inputs[0].resource, "pwm:TIM1/1");
  EXPECT_EQ(mapping.value().inputs[0].line, 4);
  ASSERT_EQ(mapping.value().outputs.size(), 1u);
  EXPECT_EQ(mapping.value().outputs[0].resource, "adc:ADC1/6");
  ASSERT_EQ(mapping.value().settings.size(), 1u);
  EXPECT_EQ(mapping.value().settings[0].value, 0.05);
  EXPECT_TRUE(check_fmu_mapping(mapping.value(), lag_description()).ok());

  ASSERT_TRUE(add_setting(mapping.value(), "k=true").ok());
  EXPECT_EQ(mapping.value().settings.back().value, 1.0);
  EXPECT_EQ(add_setting(mapping.value(), "k").error(), "--fmu-set 'k': write NAME=VALUE");
  EXPECT_EQ(add_setting(mapping.value(), "k=fast").error(),
            "--fmu-set 'k=fast': 'fast' is not a number, true or false");
  ASSERT_TRUE(add_setting(mapping.value(), "time=1").ok());
  EXPECT_EQ(check_fmu_mapping(mapping.value(), lag_description()).error(),
            "--fmu-set 'time=1': 'time' (independent, continuous) takes no value from outside");
}

TEST_F(MappingTest, SaysWhereAndWhatIsWrong) {
  const std::string connected_u = "inputs:\n  - {variable: u, resource: \"pwm:TIM1/1\"}\n";
  EXPECT_EQ(problem("inputs: [{variable: u, resource: \"pwm:TIM1/1\"}]\noutput: []\n"),
            "M:2: unknown key 'output' (did you mean 'outputs'?)");
  EXPECT_EQ(problem("inputs:\n  - {variable: uu, resource: \"pwm:TIM1/1\"}\n"),
            "M:2: the FMU has no variable 'uu' (did you mean 'u'?)");
  EXPECT_EQ(problem(connected_u + "outputs:\n  - {variable: u, resource: \"adc:ADC1/6\"}\n"),
            "M:4: 'u' is input, not an output of the FMU: under outputs only the FMU's outputs meet resources");
  EXPECT_EQ(problem("inputs:\n  - {variable: y, resource: \"pwm:TIM1/1\"}\n"),
            "M:2: 'y' is output, not an input of the FMU: under inputs only the FMU's inputs meet resources");
  EXPECT_EQ(problem(connected_u + "outputs:\n  - {variable: T, resource: \"adc:ADC1/6\"}\n"),
            "M:4: 'T' is parameter, not an output of the FMU: under outputs only the FMU's outputs meet resources");
  EXPECT_EQ(problem(connected_u + "outputs:\n  - {variable: time, resource: adc:ADC1/6, unit: ms}\n"),
            "M:4: 'time' is independent, not an output of the FMU: under outputs only the FMU's outputs meet "
            "resources");
  EXPECT_EQ(problem("outputs: []\n"),
            "M: the FMU's input 'u' is connected to no resource (under inputs) and given no value (under set)");
  EXPECT_TRUE(problem("set: {u: 1}\n").empty());  // an input held at a value needs no connection
  EXPECT_EQ(problem(connected_u + "  - {variable: u, resource: \"pwm:TIM1/2\"}\n"),
            "M:3: 'u' is connected on line 2 already");
  EXPECT_EQ(problem(connected_u + "outputs:\n  - {variable: y, resource: adc:A}\n  - {variable: y, resource: adc:A}\n"),
            "M:5: adc:A element 0 is answered on line 4 already");
  EXPECT_EQ(problem(connected_u + "set: {k: fast}\n"), "M:3: k: expected a number, true or false");
  EXPECT_EQ(problem(connected_u + "set: {y: 1, time: 2}\n"),
            "M:3: 'time' (independent, continuous) takes no value from outside");
  EXPECT_EQ(problem(connected_u + "observe: [yy]\n"), "M: observe: the FMU has no variable 'yy' (did you mean 'y'?)");
  EXPECT_EQ(problem("inputs:\n  - {variable: u, resource: TIM1}\n"),
            "M:2: resource \"TIM1\" is not kind:NAME (e.g. \"adc:ADC1/6\")");
  EXPECT_EQ(problem("inputs:\n  - {variable: u, resource: pwm:T, element: -1}\n"),
            "M:2: element: expected an index 0..65535");
  EXPECT_EQ(problem("inputs:\n  - {resource: pwm:T}\n"), "M:2: needs variable");
  EXPECT_EQ(problem("inputs: [\n"), "M:2: end of sequence flow not found");
}

TEST_F(MappingTest, RefusesUnitsThatDiffer) {
  auto description = lag_description();
  description.variables[1].unit = "V";  // u
  const std::string file = write("inputs:\n  - {variable: u, resource: \"pwm:TIM1/1\", unit: mV}\n");
  EXPECT_EQ(check_fmu_mapping(read_fmu_mapping(file).value(), description).error(),
            file + ":2: unit 'mV' differs from the FMU's 'V' for 'u'");
  const std::string same = write("inputs:\n  - {variable: u, resource: \"pwm:TIM1/1\", unit: V}\n");
  EXPECT_TRUE(check_fmu_mapping(read_fmu_mapping(same).value(), description).ok());
}

}  // namespace
}  // namespace duet::fmu_plant
