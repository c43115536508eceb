// modelDescription.xml: the test FMUs' descriptions read, malformed ones refused with their line and problem, and
// the writer's output read back as what was written.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "duet/fmi/model_description_reader.hpp"
#include "duet/fmi/model_description_writer.hpp"

namespace duet::fmi {
namespace {

std::string fixture(const std::string& name) {
  std::ostringstream text;
  text << std::ifstream{std::string{DUET_FMI_TESTING_DIR} + "/" + name}.rdbuf();
  EXPECT_FALSE(text.str().empty()) << name;
  return text.str();
}

TEST(ModelDescription, ReadsTheFirstOrderLagOfBothVersions) {
  for (const std::string file : {"models/first_order_lag_fmi2.xml", "models/first_order_lag_fmi3.xml"}) {
    SCOPED_TRACE(file);
    auto description = read_model_description(fixture(file));
    ASSERT_TRUE(description) << description.error();
    const ModelDescription& lag = description.value();
    const bool v2 = file.find("fmi2") != std::string::npos;
    EXPECT_EQ(lag.version, v2 ? FmiVersion::v2 : FmiVersion::v3);
    EXPECT_EQ(lag.model_name, "FirstOrderLag");
    EXPECT_EQ(lag.token, v2 ? "{duet-test-first-order-lag-fmi2}" : "{duet-test-first-order-lag-fmi3}");
    EXPECT_EQ(lag.co_simulation.model_identifier, "FirstOrderLag");
    EXPECT_TRUE(lag.co_simulation.can_handle_variable_communication_step_size);
    EXPECT_FALSE(lag.co_simulation.can_be_instantiated_only_once_per_process);
    EXPECT_EQ(lag.default_experiment, (DefaultExperiment{.start_time = 0.0, .stop_time = 2.0, .step_size = 0.01}));
    EXPECT_EQ(lag.units, std::vector<std::string>{"s"});
    ASSERT_EQ(lag.variables.size(), 5u);
    const Variable u{.name = "u",
                     .value_reference = 1,
                     .type = v2 ? VariableType::real : VariableType::float64,
                     .causality = Causality::input,
                     .variability = Variability::continuous,
                     .initial = v2 ? Initial::none : Initial::exact,  // the defaults of each version
                     .start = "0",
                     .unit = "",
                     .description = "input"};
    EXPECT_EQ(lag.variables[1], u);
    EXPECT_EQ(lag.variables[3].variability, Variability::tunable);
    EXPECT_EQ(lag.variables[3].initial, Initial::exact);
    EXPECT_EQ(lag.variables[3].unit, "s");
    EXPECT_EQ(lag.variables[0].causality, Causality::independent);
    EXPECT_EQ(lag.outputs, std::vector<std::size_t>{2});
  }
}

TEST(ModelDescription, ReadsEveryTestModel) {
  for (const std::string model : {"first_order_lag", "double_integrator", "terminating", "failing"})
    for (const std::string version : {"_fmi2.xml", "_fmi3.xml"}) {
      auto description = read_model_description(fixture("models/" + model + version));
      EXPECT_TRUE(description) << model << version << ": " << description.error();
    }
}

struct Malformed {
  std::string file;
  std::string message;
};

class MalformedDescription : public ::testing::TestWithParam<Malformed> {};

TEST_P(MalformedDescription, IsRefusedWithItsLineAndProblem) {
  auto description = read_model_description(fixture("malformed/" + GetParam().file));
  ASSERT_FALSE(description);
  EXPECT_EQ(description.error(), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Variants, MalformedDescription,
    ::testing::Values(
        Malformed{"not_well_formed.xml",
                  "modelDescription.xml:3: not well-formed XML: Error parsing start element tag"},
        Malformed{"wrong_root.xml",
                  "modelDescription.xml:2: the root element is <modelDescription>, not <fmiModelDescription>"},
        Malformed{"no_token.xml", "modelDescription.xml:2: <fmiModelDescription> has no instantiationToken attribute"},
        Malformed{"unknown_version.xml", "modelDescription.xml:2: fmiVersion \"1.0\" is neither 2.0 nor 3.0"},
        Malformed{"no_co_simulation.xml",
                  "modelDescription.xml:2: no <CoSimulation> element: duet runs co-simulation FMUs only"},
        Malformed{"identifier_not_c.xml",
                  "modelDescription.xml:3: modelIdentifier \"my-model\" is not a C identifier "
                  "(it names the shared library and its functions)"},
        Malformed{"duplicate_value_reference.xml",
                  "modelDescription.xml:7: \"n\": valueReference 1 is the one of \"y\" (line 6) already"},
        Malformed{"duplicate_name.xml", "modelDescription.xml:7: variable name \"y\" is used twice (first on line 6)"},
        Malformed{"parameter_continuous.xml",
                  "modelDescription.xml:7: \"gain\": causality parameter cannot have variability continuous"},
        Malformed{"input_without_start.xml", "modelDescription.xml:7: \"u\": needs a start value (causality input)"},
        Malformed{"calculated_with_start.xml",
                  "modelDescription.xml:6: \"y\": may not have a start value (initial calculated)"},
        Malformed{"two_independent.xml",
                  "modelDescription.xml:7: \"t2\": a second independent variable (the first is \"time\")"},
        Malformed{"output_not_listed.xml", "modelDescription.xml:6: output \"y\" is not listed in <ModelStructure>"},
        Malformed{"output_unknown_reference.xml",
                  "modelDescription.xml:10: <Output valueReference=\"7\">: no variable has that value reference"},
        Malformed{"integer_continuous.xml", "modelDescription.xml:7: \"n\": Int32 variables cannot be continuous"},
        Malformed{"unknown_causality.xml",
                  "modelDescription.xml:7: causality \"sideways\" is not one of parameter, "
                  "calculatedParameter, input, output, local, independent, "
                  "structuralParameter"},
        Malformed{"bad_value_reference.xml",
                  "modelDescription.xml:7: valueReference \"-2\" is not an unsigned integer"},
        Malformed{"no_independent.xml",
                  "modelDescription.xml:4: no independent variable (FMI 3.0 needs one, usually \"time\")"},
        Malformed{"input_initial_calculated.xml",
                  "modelDescription.xml:7: \"u\": an input's initial can only be exact"},
        Malformed{"fmi2_integer_without_variability.xml",
                  "modelDescription.xml:5: \"n\": Integer variables cannot be continuous (the default; say "
                  "variability=\"discrete\")"},
        Malformed{"fmi2_duplicate_value_reference.xml",
                  "modelDescription.xml:8: \"b\": an alias of \"a\" (line 5) (same valueReference), and both have a "
                  "start value"},
        Malformed{"fmi2_input_with_initial.xml",
                  "modelDescription.xml:5: \"u\": an input has no initial attribute in FMI 2.0"},
        Malformed{"fmi2_no_type_element.xml",
                  "modelDescription.xml:5: \"u\" has no type element (Real, Integer, Boolean, String, Enumeration)"},
        Malformed{"fmi2_unknown_index.xml",
                  "modelDescription.xml:12: <Unknown index=\"5\">: there is no variable 5 (<ModelVariables> has 1)"}),
    [](const ::testing::TestParamInfo<Malformed>& variant) {
      return variant.param.file.substr(0, variant.param.file.find('.'));
    });

ModelDescription example(FmiVersion version) {
  const bool v2 = version == FmiVersion::v2;
  ModelDescription description{
      .version = version,
      .model_name = "Example",
      .token = "{0d8c7ad1-example}",
      .description = "every kind of variable duet writes",
      .generation_tool = "duet",
      .co_simulation = {.model_identifier = "Example",
                        .can_handle_variable_communication_step_size = true,
                        .can_be_instantiated_only_once_per_process = true,
                        .needs_execution_tool = false,
                        .fixed_internal_step_size = v2 ? std::nullopt : std::optional<double>{0.001}},
      .default_experiment = DefaultExperiment{.start_time = 0.0, .stop_time = 10.0, .step_size = 0.01},
      .units = {"s", "rad"},
      .variables = {},
      .outputs = {2, 4}};
  const VariableType real = v2 ? VariableType::real : VariableType::float64;
  const VariableType integer = v2 ? VariableType::integer : VariableType::int32;
  description.variables = {
      {.name = "time", .value_reference = 0, .type = real, .causality = Causality::independent, .unit = "s"},
      {.name = "torque",
       .value_reference = 1,
       .type = real,
       .causality = Causality::input,
       .initial = v2 ? Initial::none : Initial::exact,
       .start = "0"},
      {.name = "theta",
       .value_reference = 2,
       .type = real,
       .causality = Causality::output,
       .initial = Initial::calculated,
       .unit = "rad",
       .description = "tilt"},
      {.name = "gain",
       .value_reference = 3,
       .type = real,
       .causality = Causality::parameter,
       .variability = Variability::tunable,
       .initial = Initial::exact,
       .start = "0.1"},
      {.name = "mode",
       .value_reference = 4,
       .type = integer,
       .causality = Causality::output,
       .variability = Variability::discrete,
       .initial = Initial::exact,
       .start = "2"},
      {.name = "enabled",
       .value_reference = 5,
       .type = VariableType::boolean,
       .causality = Causality::parameter,
       .variability = Variability::fixed,
       .initial = Initial::exact,
       .start = "true"},
      {.name = "label",
       .value_reference = 6,
       .type = VariableType::string,
       .causality = Causality::parameter,
       .variability = Variability::fixed,
       .initial = Initial::exact,
       .start = "robot"},
  };
  return description;
}

TEST(ModelDescriptionWriter, WritesWhatTheReaderReadsBackForBothVersions) {
  for (const FmiVersion version : {FmiVersion::v2, FmiVersion::v3}) {
    const ModelDescription written = example(version);
    auto xml = write_model_description(written);
    ASSERT_TRUE(xml) << xml.error();
    auto read = read_model_description(xml.value());
    ASSERT_TRUE(read) << read.error() << "\n" << xml.value();
    EXPECT_EQ(read.value(), written) << xml.value();
  }
}

TEST(ModelDescriptionWriter, WritesTheSchemasElementOrder) {
  const std::string xml = write_model_description(example(FmiVersion::v3)).value();
  std::size_t last = 0;
  for (const std::string element : {"<CoSimulation", "<UnitDefinitions", "<DefaultExperiment", "<ModelVariables",
                                    "<ModelStructure", "<Output ", "<InitialUnknown "}) {
    const std::size_t at = xml.find(element);
    ASSERT_NE(at, std::string::npos) << element;
    EXPECT_GT(at, last) << element;
    last = at;
  }
  EXPECT_NE(xml.find("<String name=\"label\" valueReference=\"6\" causality=\"parameter\" variability=\"fixed\" "
                     "initial=\"exact\">\n      <Start value=\"robot\" />"),
            std::string::npos)
      << xml;
  const std::string xml2 = write_model_description(example(FmiVersion::v2)).value();
  EXPECT_NE(xml2.find("<Outputs>\n      <Unknown index=\"3\" />\n      <Unknown index=\"5\" />\n    </Outputs>\n"
                      "    <InitialUnknowns>\n      <Unknown index=\"3\" />\n    </InitialUnknowns>"),
            std::string::npos)
      << xml2;
}

TEST(ModelDescriptionWriter, RefusesWhatItCannotDescribeWhole) {
  ModelDescription description = example(FmiVersion::v2);
  description.variables[4].type = VariableType::enumeration;
  EXPECT_EQ(write_model_description(description).error(),
            "variable \"mode\": enumerations need type definitions, which duet does not write");
  description.variables[4].type = VariableType::float32;
  EXPECT_EQ(write_model_description(description).error(), "variable \"mode\": Float32 is not a type of FMI 2.0");
}

}  // namespace
}  // namespace duet::fmi
