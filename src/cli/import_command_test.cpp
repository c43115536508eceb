// `duet import simulink` as a user types it: a model imported with its variables and its report, one refused with
// every reason, and command lines it refuses.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "duet/fmi/archive_writer.hpp"
#include "duet/support/temporary_folder.hpp"
#include "duet/support/text_file.hpp"
#include "run_for_test.hpp"

namespace duet::cli {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path testing = DUET_SOURCE_DIR "/src/simulink_import/testing";

// The hand-written R2019b package zipped into an .slx, as Simulink saves it.
std::filesystem::path tilt_loop_slx(const std::filesystem::path& folder) {
  const std::filesystem::path parts = testing / "slx_r2019b";
  std::vector<fmi::ArchiveInput> inputs;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(parts)) {
    if (!entry.is_regular_file()) continue;
    inputs.push_back({std::filesystem::relative(entry.path(), parts).generic_string(), entry.path()});
  }
  const std::filesystem::path slx = folder / "tilt_loop.slx";
  EXPECT_TRUE(fmi::write_archive(slx, inputs));
  return slx;
}

TEST(ImportCommand, AModelWithItsVariablesIsWrittenCheckedAndReported) {
  auto folder = TemporaryFolder::make("import_command_test_").value();
  const std::filesystem::path variables = folder.path() / "parameters.m";
  std::ofstream{variables} << "% the controller's parameters\nTs = 0.01;  % s\nKp = 2;\n";
  const std::string output = (folder.path() / "tilt_loop.yaml").string();
  const Outcome outcome = run({"import", "simulink", tilt_loop_slx(folder.path()).string(), "--variables",
                               variables.string(), "-o", output, "--report"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  EXPECT_THAT(outcome.out, HasSubstr("  ok       tilt_loop/Proportional Gain (Gain): Gain k: Kp\n"));
  EXPECT_THAT(outcome.out, HasSubstr("11 of 11 blocks imported\n"));
  EXPECT_THAT(outcome.out, HasSubstr("imported tilt_loop (slx (blockdiagram.xml)) as " + output + "\n"));
  EXPECT_THAT(read_text_file(output).value(), HasSubstr("  Kp: {value: 2, "));
  // The model checks, and simulates like any other.
  const Outcome simulated =
      run({"sim", output, "--duration", "0.05", "--csv", (folder.path() / "t.csv").string(), "--no-plot"});
  EXPECT_EQ(simulated.exit_code, ExitCode::success) << simulated.err;
  // It generates, and its variable Kp stays a tunable parameter of that name: a CHARACTERISTIC of the A2L.
  const std::string generated = (folder.path() / "generated").string();
  const Outcome gen = run({"gen", output, "-o", generated});
  ASSERT_EQ(gen.exit_code, ExitCode::success) << gen.err;
  EXPECT_THAT(read_text_file(generated + "/tilt_loop.a2l").value(), HasSubstr("/begin CHARACTERISTIC Kp "));
  // And it renders as a diagram.
  const Outcome rendered = run({"model", "render", output, "-o", (folder.path() / "tilt_loop.svg").string()});
  EXPECT_EQ(rendered.exit_code, ExitCode::success) << rendered.err;
  EXPECT_THAT(read_text_file((folder.path() / "tilt_loop.svg").string()).value(), HasSubstr("<svg"));
}

TEST(ImportCommand, WithoutItsVariablesNothingIsWrittenAndEveryProblemIsSaid) {
  auto folder = TemporaryFolder::make("import_command_test_").value();
  const std::string output = (folder.path() / "tilt_loop.yaml").string();
  const Outcome outcome = run({"import", "simulink", tilt_loop_slx(folder.path()).string(), "-o", output});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err,
            "duet import simulink: tilt_loop: the fixed step 'Ts' cannot be evaluated: column 1: unresolved name "
            "'Ts'; give --variables or --base-period-us\n"
            "duet import simulink: nothing written: 1 problem(s) (--report lists every block with its verdict)\n");
  EXPECT_FALSE(std::filesystem::exists(output));

  const Outcome no_gain =
      run({"import", "simulink", tilt_loop_slx(folder.path()).string(), "--base-period-us", "10000", "-o", output});
  EXPECT_EQ(no_gain.exit_code, ExitCode::failure);
  EXPECT_THAT(no_gain.err, HasSubstr("duet import simulink: tilt_loop/Proportional Gain (Gain): Gain 'Kp': column 1: "
                                     "unresolved name 'Kp'\n"));
}

// A Sum of int16 signals that saturates in Simulink imports block by block, but the checked model shows its type:
// duet's Sum wraps, so the import is refused and its file removed.
TEST(ImportCommand, IntegersThatSimulinkSaturatesAreRefusedOnceTheModelIsChecked) {
  auto folder = TemporaryFolder::make("import_command_test_").value();
  const std::filesystem::path mdl = folder.path() / "ints.mdl";
  std::ofstream{mdl} << "Model {\n  Name \"ints\"\n  System {\n    Name \"ints\"\n"
                        "    Block {\n      BlockType Inport\n      Name \"u\"\n      SID \"1\"\n    }\n"
                        "    Block {\n      BlockType DataTypeConversion\n      Name \"to int16\"\n      SID \"2\"\n"
                        "      OutDataTypeStr \"int16\"\n      RndMeth \"Zero\"\n"
                        "      SaturateOnIntegerOverflow on\n    }\n"
                        "    Block {\n      BlockType Sum\n      Name \"twice\"\n      SID \"3\"\n"
                        "      Inputs \"++\"\n      SaturateOnIntegerOverflow on\n    }\n"
                        "    Block {\n      BlockType Outport\n      Name \"y\"\n      SID \"4\"\n    }\n"
                        "    Line {\n      SrcBlock \"u\"\n      SrcPort 1\n      DstBlock \"to int16\"\n"
                        "      DstPort 1\n    }\n"
                        "    Line {\n      SrcBlock \"to int16\"\n      SrcPort 1\n"
                        "      Branch {\n        DstBlock \"twice\"\n        DstPort 1\n      }\n"
                        "      Branch {\n        DstBlock \"twice\"\n        DstPort 2\n      }\n    }\n"
                        "    Line {\n      SrcBlock \"twice\"\n      SrcPort 1\n      DstBlock \"y\"\n"
                        "      DstPort 1\n    }\n  }\n}\n";
  const std::string output = (folder.path() / "ints.yaml").string();
  const Outcome outcome = run({"import", "simulink", mdl.string(), "--base-period-us", "1000", "-o", output});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err,
            "duet import simulink: ints/twice (Sum): it computes in int16: Simulink saturates an integer overflow "
            "(SaturateOnIntegerOverflow on), duet's Sum wraps (set it off in Simulink, or compute in floating point)\n"
            "duet import simulink: nothing written: 1 problem(s)\n");
  EXPECT_FALSE(std::filesystem::exists(output));
}

TEST(ImportCommand, BadCommandLines) {
  const Outcome interrupt =
      run({"import", "simulink", (testing / "controller.mdl").string(), "-o", "x.yaml", "--interrupt", "model/ISR"});
  EXPECT_EQ(interrupt.exit_code, ExitCode::usage);
  EXPECT_EQ(interrupt.err,
            "duet import simulink: --interrupt 'model/ISR': write BLOCK_PATH=IRQ:PRIORITY (model/ISR=TIM2:3)\n");
  const Outcome variables = run({"import", "simulink", (testing / "controller.mdl").string(), "-o", "x.yaml",
                                 "--variables", (testing / "controller.mdl").string()});
  EXPECT_EQ(variables.exit_code, ExitCode::failure);
  EXPECT_THAT(variables.err, HasSubstr("variables come from a .m script or a .yaml file"));
}

}  // namespace
}  // namespace duet::cli
