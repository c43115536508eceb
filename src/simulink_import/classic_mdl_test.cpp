// The classic .mdl reader on a hand-written controller (testing/controller.mdl, ISO-8859-1) and on damaged files.
#include "duet/simulink_import/classic_mdl.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

namespace duet::simulink_import {
namespace {

using Parameters = std::map<std::string, std::string>;

std::string file_bytes(const std::string& name) {
  std::ifstream in{std::string{DUET_SIMULINK_TESTING_DIR} + "/" + name, std::ios::binary};
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::string describe(const Endpoint& end) { return end.block + " " + end.kind + " " + std::to_string(end.port); }

// "name: source -> destination, destination" in the order the file gives them.
std::vector<std::string> describe(const std::vector<Line>& lines) {
  std::vector<std::string> described;
  for (const Line& line : lines) {
    std::string text = line.name + ": " + (line.source ? describe(*line.source) : "(none)") + " ->";
    for (const Endpoint& destination : line.destinations) text += " " + describe(destination) + ",";
    described.push_back(text);
  }
  return described;
}

std::vector<std::string> names_of(const System& system) {
  std::vector<std::string> names;
  for (const Block& block : system.blocks) names.push_back(block.type + " " + block.name + " #" + block.sid);
  return names;
}

const Block& block_named(const System& system, const std::string& name) {
  for (const Block& block : system.blocks)
    if (block.name == name) return block;
  throw std::runtime_error{"no block " + name};
}

SimulinkModel controller() {
  Result<SimulinkModel> model = read_classic_mdl(file_bytes("controller.mdl"), "controller.mdl");
  if (!model) throw std::runtime_error{model.error()};
  return std::move(model).value();
}

TEST(ClassicMdl, ReadsTheModelItsSolverAndItsDefaults) {
  const SimulinkModel model = controller();
  EXPECT_EQ(model.name, "balance_controller");
  EXPECT_EQ(model.format, "mdl (classic)");
  EXPECT_EQ(model.release, "");  // `Version 9.0` alone names no release
  EXPECT_EQ(model.root.part, "controller.mdl");
  EXPECT_EQ(model.solver.parameters, (Parameters{{"Version", "1.17.0"},
                                                 {"StartTime", "0.0"},
                                                 {"StopTime", "10.0"},
                                                 {"FixedStep", "0.005"},
                                                 {"Solver", "FixedStepDiscrete"},
                                                 {"SolverName", "FixedStepDiscrete"},
                                                 {"SolverMode", "SingleTasking"},
                                                 {"EnableMultiTasking", "off"}}));
  const std::map<std::string, Parameters> defaults{{"Gain", {{"Gain", "1"}, {"Multiplication", "Element-wise(K.*u)"}}},
                                                   {"Sum", {{"IconShape", "rectangular"}, {"Inputs", "++"}}},
                                                   {"UnitDelay", {{"InitialCondition", "0"}, {"SampleTime", "1"}}}};
  EXPECT_EQ(model.defaults, defaults);
}

TEST(ClassicMdl, ReadsTheRootSystemsBlocksInFileOrderConvertedToUtf8) {
  const SimulinkModel model = controller();
  EXPECT_THAT(
      names_of(model.root),
      testing::ElementsAre("Inport theta #1", "Inport theta rate #2", "Gain Verst\xC3\xA4rkung #3", "Sum Sum #4",
                           "UnitDelay Unit\nDelay #5", "SubSystem Filter #6", "Reference Discrete PID Controller #10",
                           "SubSystem Logger #11", "Outport torque #15"));
  EXPECT_EQ(block_named(model.root, "theta").parameters, (Parameters{{"Position", "[20, 98, 50, 112]"}}));
  EXPECT_EQ(block_named(model.root, "theta rate").parameters,
            (Parameters{{"Position", "[20, 198, 50, 212]"}, {"Port", "2"}, {"OutDataTypeStr", "boolean"}}));
  // Two quoted chunks on consecutive lines are one value.
  EXPECT_EQ(block_named(model.root, "Verst\xC3\xA4rkung").parameters, (Parameters{{"Gain", "K_theta.*scale"}}));
  const Block& sum = block_named(model.root, "Sum");
  EXPECT_EQ(sum.parameters, (Parameters{{"Ports", "[2, 1]"}, {"Inputs", "|+-"}}));
  EXPECT_EQ(sum.output_names, (std::map<int, std::string>{{1, "Regelabweichung \xC2\xB1"}}));
  EXPECT_EQ(block_named(model.root, "Unit\nDelay").parameters,
            (Parameters{{"InitialCondition", "0"}, {"SampleTime", "Ts"}}));
  EXPECT_EQ(block_named(model.root, "theta").line, 69);
  EXPECT_EQ(block_named(model.root, "torque").line, 226);
}

TEST(ClassicMdl, ReadsAMaskedSubsystemWithItsContents) {
  const SimulinkModel model = controller();
  const Block& filter = block_named(model.root, "Filter");
  EXPECT_EQ(filter.parameters, (Parameters{{"Ports", "[1, 1]"}}));
  EXPECT_EQ(filter.mask_parameters, (Parameters{{"Ts", "0.005"}, {"alpha", "0.9"}}));
  ASSERT_EQ(filter.systems.size(), 1U);
  const System& inside = filter.systems[0];
  EXPECT_THAT(names_of(inside), testing::ElementsAre("Inport in #7", "Gain alpha #8", "Outport out #9"));
  EXPECT_EQ(block_named(inside, "alpha").parameters, (Parameters{{"Gain", "alpha"}}));
  EXPECT_THAT(describe(inside.lines), testing::ElementsAre(": in out 1 -> alpha in 1,", ": alpha out 1 -> out in 1,"));
}

TEST(ClassicMdl, KeepsALibraryLinksFlattenedMaskValuesAsParameters) {
  const SimulinkModel model = controller();
  const Block& pid = block_named(model.root, "Discrete PID Controller");
  EXPECT_EQ(pid.parameters, (Parameters{{"Ports", "[1, 1]"},
                                        {"SourceBlock", "simulink/Continuous/PID Controller"},
                                        {"SourceType", "PID 1dof"},
                                        {"Controller", "PI"},
                                        {"Form", "Parallel"},
                                        {"TimeDomain", "Discrete-time"},
                                        {"SampleTime", "Ts"},
                                        {"IntegratorMethod", "Forward Euler"},
                                        {"P", "3500"},
                                        {"I", "Ki"},
                                        {"LimitOutput", "on"},
                                        {"UpperSaturationLimit", "Prop.MaxForce"},
                                        {"LowerSaturationLimit", "-Prop.MaxForce"},
                                        {"AntiWindupMode", "clamping"},
                                        {"ControllerParametersSource", "internal"},
                                        {"InitialConditionSource", "internal"},
                                        {"InitialConditionForIntegrator", "0"},
                                        {"ExternalReset", "none"},
                                        {"TrackingMode", "off"}}));
  EXPECT_TRUE(pid.mask_parameters.empty());
  EXPECT_TRUE(pid.systems.empty());
}

TEST(ClassicMdl, FlattensBranchesAndReadsSpecialPorts) {
  const SimulinkModel model = controller();
  EXPECT_THAT(describe(model.root.lines),
              testing::ElementsAre("tilt: theta out 1 -> Verst\xC3\xA4rkung in 1, Filter in 1, Logger in 1,",
                                   ": Verst\xC3\xA4rkung out 1 -> Sum in 1,",  // its second branch ends nowhere
                                   ": Filter out 1 -> Sum in 2,", ": Sum out 1 -> Discrete PID Controller in 1,",
                                   ": Discrete PID Controller out 1 -> Unit\nDelay in 1,",
                                   ": Unit\nDelay out 1 -> torque in 1,", ": theta rate out 1 -> Logger trigger 1,"));
  const Block& logger = block_named(model.root, "Logger");
  ASSERT_EQ(logger.systems.size(), 1U);
  EXPECT_EQ(block_named(logger.systems[0], "Trigger").parameters,
            (Parameters{{"TriggerType", "rising"}, {"InitialTriggerSignalState", "zero"}}));
  EXPECT_THAT(describe(logger.systems[0].lines), testing::ElementsAre(": u out 1 -> Terminator in 1,"));
}

// A model around `system_body`, in UTF-8 unless the text says otherwise.
std::string model_with(const std::string& system_body, const std::string& model_extra = "") {
  return "Model {\n  Name \"m\"\n" + model_extra + "  System {\n    Name \"m\"\n" + system_body + "  }\n}\n";
}

Result<SimulinkModel> read(const std::string& text) { return read_classic_mdl(text, "model.mdl"); }

TEST(ClassicMdl, ConvertsWindows1252AndUtf8AndNamesTheReleaseADescriptionGives) {
  const std::string windows = model_with("    Block {\n      BlockType Gain\n      Name \"\x80 per kg\"\n    }\n",
                                         "  SavedCharacterEncoding \"windows-1252\"\n");
  ASSERT_TRUE(read(windows)) << read(windows).error();
  EXPECT_EQ(read(windows).value().root.blocks[0].name, "\xE2\x82\xAC per kg");
  const std::string utf8 = model_with("    Block {\n      BlockType Gain\n      Name \"\xCE\xB8 gain\"\n    }\n",
                                      "  SavedCharacterEncoding \"UTF-8\"\n  Description \"Simulink model saved in "
                                      "R2019b\"\n");
  ASSERT_TRUE(read(utf8)) << read(utf8).error();
  EXPECT_EQ(read(utf8).value().root.blocks[0].name, "\xCE\xB8 gain");
  EXPECT_EQ(read(utf8).value().release, "R2019b");
}

TEST(ClassicMdl, ReadsAOneParameterMaskAndLeavesUnnamedElementsAside) {
  const std::string text = model_with(
      "    Block {\n      BlockType SubSystem\n      Name \"S\"\n"
      "      Object {\n        $PropName \"MaskObject\"\n        Object {\n          $PropName \"Parameters\"\n"
      "          Name \"Ts\"\n          Value \"0.05\"\n        }\n      }\n      \"an element without a name\"\n      "
      "{\n        Unnamed 1\n      }\n"
      "      System {\n      }\n    }\n"
      "    Line {\n      SrcBlock \"S\"\n      SrcPort 1\n    }\n"
      "    Line {\n      DstBlock \"S\"\n      DstPort enable\n    }\n");
  const Result<SimulinkModel> model = read(text);
  ASSERT_TRUE(model) << model.error();
  const Block& block = model.value().root.blocks.at(0);
  EXPECT_TRUE(block.parameters.empty());
  EXPECT_EQ(block.mask_parameters, (Parameters{{"Ts", "0.05"}}));
  EXPECT_THAT(describe(model.value().root.lines), testing::ElementsAre(": S out 1 ->", ": (none) -> S enable 1,"));
}

TEST(ClassicMdl, UsesTheOnlyConfigurationSetWhenNoneIsNamedActive) {
  const std::string text =
      model_with("",
                 "  Array {\n    Simulink.ConfigSet {\n      $ObjectID 4\n      Array {\n        Simulink.SolverCC {\n"
                 "          FixedStep \"Ts\"\n        }\n      }\n    }\n  }\n");
  ASSERT_TRUE(read(text)) << read(text).error();
  EXPECT_EQ(read(text).value().solver.parameters, (Parameters{{"FixedStep", "Ts"}}));
}

TEST(ClassicMdl, FindsTheActiveConfigurationSetWhateverSectionNamesIt) {
  const std::string sets =
      "  Array {\n    Simulink.ConfigSet {\n      $ObjectID 4\n      Array {\n        Simulink.SolverCC {\n"
      "          FixedStep \"0.01\"\n        }\n      }\n    }\n    Simulink.ConfigSet {\n      $ObjectID 5\n"
      "      Array {\n        Simulink.SolverCC {\n          FixedStep \"0.002\"\n        }\n      }\n    }\n  }\n";
  const std::string text =
      model_with("", sets + "  Simulink.ConfigSet {\n    $PropName \"ActiveConfigurationSet\"\n    $ObjectID 5\n  }\n");
  ASSERT_TRUE(read(text)) << read(text).error();
  EXPECT_EQ(read(text).value().solver.parameters, (Parameters{{"FixedStep", "0.002"}}));
}

struct Malformed {
  std::string text;
  std::string message;
};

class ClassicMdlMalformed : public testing::TestWithParam<Malformed> {};

TEST_P(ClassicMdlMalformed, IsRefusedNamingTheLine) {
  const Result<SimulinkModel> model = read(GetParam().text);
  ASSERT_FALSE(model);
  EXPECT_EQ(model.error(), GetParam().message);
}

const std::string gain = "    Block {\n      BlockType Gain\n      Name \"Gain1\"\n    }\n";

INSTANTIATE_TEST_SUITE_P(
    Inputs, ClassicMdlMalformed,
    testing::Values(
        Malformed{"", "model.mdl:1: no 'Model { ... }' section: not a classic Simulink model file"},
        Malformed{"Library {\n  Name \"lib\"\n}\n",
                  "model.mdl:1: a block library, not a model: import a model that uses it instead"},
        Malformed{"Model {\n  Name \"m\n}\n",
                  "model.mdl:2: string not terminated: '\"' expected before the end of the line"},
        Malformed{"Model {\n  Name \"m\"\n  System {\n",
                  "model.mdl:4: the file ends inside 'System' (line 3): '}' expected"},
        Malformed{"Model {\n}\n}\n", "model.mdl:3: '}' without a section it closes"},
        Malformed{"Model {\n  Name\n}\n", "model.mdl:2: 'Name' has neither a value nor a '{' after it on its line"},
        Malformed{"Model {\n  Location [1, 2\n}\n",
                  "model.mdl:2: array not closed: ']' expected before the end of the line"},
        Malformed{"Model {\n  Points 1, 2]\n}\n", "model.mdl:2: ']' without an array it closes"},
        Malformed{"Model {\n  Version 9.0\n}\n", "model.mdl:1: the model has no Name"},
        Malformed{model_with("    Block {\n      Name \"Gain1\"\n    }\n"),
                  "model.mdl:5: block 'Gain1' without a BlockType"},
        Malformed{model_with("    Block {\n      BlockType Gain\n    }\n"), "model.mdl:5: Gain block without a Name"},
        Malformed{model_with(gain + gain), "model.mdl:9: two blocks named 'Gain1' in system 'm' (the other on line 5)"},
        Malformed{model_with("    Block {\n      BlockType SubSystem\n      Name \"Sub\"\n      System {\n" + gain +
                             "        Line {\n          SrcBlock \"Gain2\"\n          SrcPort 1\n        }\n"
                             "      }\n    }\n"),
                  "model.mdl:14: line from 'Gain2', which system 'm/Sub' does not have"},
        Malformed{model_with(gain + "    Line {\n      DstBlock \"Gain1\"\n      DstPort enabled\n    }\n"),
                  "model.mdl:11: DstPort 'enabled' is not a port: a number, trigger, enable, ifaction, Reset, state, "
                  "LConn<n> or RConn<n>"},
        Malformed{model_with(gain + "    Line {\n      DstBlock \"Gain1\"\n    }\n"),
                  "model.mdl:10: line to 'Gain1' without DstPort"},
        Malformed{model_with("    Block {\n      BlockType Gain\n      Name \"G\"\n      Gain \"1\"\n      Gain \"2\"\n"
                             "    }\n"),
                  "model.mdl:9: 'Gain' given twice in 'Block' (line 5)"},
        Malformed{model_with("", "  SavedCharacterEncoding \"Shift_JIS\"\n"),
                  "model.mdl:3: SavedCharacterEncoding 'Shift_JIS' is not read (ISO-8859-1, windows-1252 and UTF-8 "
                  "are); save the model as UTF-8, or as .slx"},
        Malformed{model_with("    Block {\n      BlockType Gain\n      Name \"G\xE4\"\n    }\n"),
                  "model.mdl:7: byte 0xE4 is not UTF-8, and the file names no SavedCharacterEncoding"},
        Malformed{model_with("", "  SavedCharacterEncoding \"windows-1252\"\n  Description \"\x81\"\n"),
                  "model.mdl:4: byte 0x81 has no character in windows-1252"},
        Malformed{model_with("", "  Object {\n    $PropName \"ActiveConfigurationSet\"\n    $ObjectID 7\n  }\n"),
                  "model.mdl:3: ActiveConfigurationSet names $ObjectID '7', which no Simulink.ConfigSet has"},
        Malformed{model_with("    Block {\n      BlockType SubSystem\n      Name \"S\"\n      Object {\n"
                             "        $PropName \"MaskObject\"\n        Object {\n          $PropName \"Parameters\"\n"
                             "          Value \"1\"\n        }\n      }\n    }\n"),
                  "model.mdl:10: mask parameter of block 'S' without a Name"},
        Malformed{std::string(201, '{') + std::string(201, '}'), "model.mdl:1: sections nested deeper than 200"},
        Malformed{"Model {\n  Name \"m\"\n}\nModel {\n}\n",
                  "model.mdl:4: a second 'Model' section (the first on line 1)"}));

// Until the fuzz target exists: the test model cut short at many places and with bytes changed at random (fixed
// seed) either reads or is refused with a message that names a line; the sanitizers watch for anything worse.
TEST(ClassicMdl, DamagedCopiesOfTheTestModelReadOrAreRefusedWithALine) {
  const std::string original = file_bytes("controller.mdl");
  const auto check = [](const std::string& bytes) {
    const Result<SimulinkModel> model = read_classic_mdl(bytes, "controller.mdl");
    if (!model) {
      EXPECT_THAT(model.error(), testing::MatchesRegex("controller\\.mdl:[0-9]+: .+"));
    }
  };
  for (std::size_t length = 0; length < original.size(); length += 11) check(original.substr(0, length));
  std::mt19937 random{26};
  std::uniform_int_distribution<std::size_t> place{0, original.size() - 1};
  constexpr std::string_view replacements = "{}[]\"\\\n \x80\xE4x1";
  std::uniform_int_distribution<std::size_t> replacement{0, replacements.size() - 1};
  for (int copy = 0; copy < 400; ++copy) {
    std::string damaged = original;
    for (int change = 0; change < 3; ++change) damaged[place(random)] = replacements[replacement(random)];
    check(damaged);
  }
}

TEST(ClassicMdl, RefusesAModelWithoutASystem) {
  const Result<SimulinkModel> model = read("Model {\n  Name \"m\"\n}\n");
  ASSERT_FALSE(model);
  EXPECT_EQ(model.error(), "model.mdl:1: the model has no System");
}

}  // namespace
}  // namespace duet::simulink_import
