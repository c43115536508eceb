// `duet model check` as a user types it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_for_test.hpp"

namespace duet::cli {
namespace {

class ModelCommand : public ::testing::Test {
 protected:
  void write(const std::string& text) { std::ofstream{file} << text; }
  void TearDown() override { std::filesystem::remove(file); }
  const std::string file =
      (std::filesystem::temp_directory_path() / ("duet_model_" + std::to_string(::getpid()) + ".yaml")).string();
};

TEST_F(ModelCommand, CheckListsTheTasksOfAValidModel) {
  write(
      "duet_model: 1\nname: blink\nbase_period_us: 100\nblocks:\n"
      "  - {name: toggle, type: Not, inputs: {u: old}, outputs: {y: state}}\n"
      "  - {name: delay, type: UnitDelay, period: {multiple: 10}, inputs: {u: state}, outputs: {y: old}}\n"
      "  - {name: pin, type: GpioOut, parameters: {pin: PA5}, inputs: {u: state}}\n");
  const Outcome outcome = run({"model", "check", file});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.out, "blink: 3 blocks, 1 tasks\n  rate 10: every 1000 us: delay, toggle, pin\n");
  EXPECT_EQ(outcome.err, "");
}

// What a diagram of it must show: each block and each signal a system names once (a subsystem's ports inside).
TEST_F(ModelCommand, CheckCountsWhatItsDiagramShowsAsJson) {
  write(
      "duet_model: 1\nname: latch\nbase_period_us: 1000\nblocks:\n"
      "  - {name: count, type: Counter, parameters: {limit: 9}, outputs: {y: n}}\n"
      "  - {name: high, type: Compare, parameters: {operator: '>', value: 5}, inputs: {u: n}, outputs: {y: hi}}\n"
      "  - name: keep\n    type: Subsystem\n    trigger: {edge: rising, signal: hi}\n"
      "    inputs: {value: n}\n    outputs: {held: held}\n    blocks:\n"
      "      - {name: copy, type: Convert, parameters: {type: double}, inputs: {u: value}, outputs: {y: held}}\n"
      "  - {name: out, type: Outport, inputs: {u: held}}\n");
  const Outcome outcome = run({"model", "check", "--json", file});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  // n, hi, held at the top; value and held inside keep. The edge detector is scheduled but not drawn.
  EXPECT_EQ(outcome.out,
            "{\"blocks\":4,\"name\":\"latch\",\"scheduled_blocks\":5,\"subsystems\":1,"
            "\"tasks\":[{\"blocks\":5,\"name\":\"rate 1\"}],\"wires\":5}\n");
}

TEST_F(ModelCommand, CheckNamesEveryProblemAndFails) {
  write(
      "duet_model: 1\nname: blink\nbase_period_us: 100\nparameters:\n  K: 2\nblocks:\n"
      "  - {name: pin, type: GpioOut, parameters: {pin: PA5}, inputs: {u: state}}\n");
  const Outcome outcome = run({"model", "check", file});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, file +
                             ":7:65: error: input 'u' of block 'pin' reads signal 'state', which nothing drives "
                             "(an output of a block, or of the subsystem's inputs, must drive it)\n" +
                             file + ":5:3: warning: parameter 'K' is not used (remove it, or use it in a block)\n");
  EXPECT_EQ(run({"model", "check", "/nonexistent.yaml"}).err, "/nonexistent.yaml: cannot open\n");
  write("duet_model: 2\n");
  EXPECT_EQ(run({"model", "check", file}).err,
            file + ":1:13: error: this is duet model format 2; duet reads version 1\n");
}

}  // namespace
}  // namespace duet::cli

namespace duet::cli {
namespace {

TEST(ModelExamples, TheStepTimeModelChecks) {
  const Outcome outcome = run({"model", "check", std::string{DUET_SOURCE_DIR} + "/apps/step_time/step_time.yaml"});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  EXPECT_EQ(outcome.out, "step_time: 3 blocks, 1 tasks\n  rate 1: every 100 us: previous, toggle, led\n");
}

}  // namespace
}  // namespace duet::cli

namespace duet::cli {
namespace {

TEST(ModelExamples, TheStepTimeModelRendersAsSvg) {
  const std::string svg =
      (std::filesystem::temp_directory_path() / ("duet_render_" + std::to_string(::getpid()) + ".svg")).string();
  const Outcome outcome =
      run({"model", "render", std::string{DUET_SOURCE_DIR} + "/apps/step_time/step_time.yaml", "-o", svg});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  std::ifstream picture{svg};
  std::ostringstream text;
  text << picture.rdbuf();
  EXPECT_NE(text.str().find("<svg"), std::string::npos);
  EXPECT_NE(text.str().find("toggle"), std::string::npos);
  std::filesystem::remove(svg);
  const Outcome dot =
      run({"model", "render", std::string{DUET_SOURCE_DIR} + "/apps/step_time/step_time.yaml", "--dot"});
  EXPECT_NE(dot.out.find("\"previous\":\"y\" -> \"toggle\":\"u\""), std::string::npos) << dot.out;
}

}  // namespace
}  // namespace duet::cli

namespace duet::cli {
namespace {

TEST(ModelCommandCode, ACodeBlockWithItsHeaderBesideTheModel) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("duet_model_code_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::ofstream{folder / "motor_logic.hpp"} << "// declared for the test\n";
  std::ofstream{folder / "robot.yaml"}
      << "duet_model: 1\nname: robot\nbase_period_us: 100\nblocks:\n"
         "  - name: logic\n    type: Code\n    function: motor_logic\n    file: motor_logic.hpp\n"
         "    direct_feedthrough: false\n"
         "    inputs: {theta: {signal: tilt, type: boolean}}\n"
         "    outputs: {stop: {signal: stop, type: boolean}}\n"
         "    state: {last: {type: single, initial: 0}}\n"
         "    parameters: {limit: {value: 60, type: single}}\n"
         "  - {name: angle, type: GpioIn, parameters: {pin: PA0}, outputs: {y: tilt}}\n"
         "  - {name: led, type: GpioOut, parameters: {pin: PB0}, inputs: {u: stop}}\n";
  const Outcome outcome = run({"model", "check", (folder / "robot.yaml").string()});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  // Without direct feedthrough the code's output comes from its state: it runs first, as written, before the block
  // that drives its input (with feedthrough it would wait for 'angle').
  EXPECT_EQ(outcome.out, "robot: 3 blocks, 1 tasks\n  rate 1: every 100 us: logic, angle, led\n");
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace duet::cli

namespace duet::cli {
namespace {

// A problem in a referenced model is at its place in that file, not in the file checked.
TEST(ModelCommandReference, CheckNamesTheFileOfEachProblem) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("duet_model_reference_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::ofstream{folder / "controller.yaml"} << "duet_model: 1\nname: c\nbase_period_us: 100\nparameters:\n  Kd: 1\n"
                                               "blocks:\n  - {name: theta, type: Inport, outputs: {y: theta}}\n"
                                               "  - {name: limit, type: Saturation, parameters: {lower: -1, upper: 1},"
                                               " inputs: {u: thetta}, outputs: {y: duty}}\n"
                                               "  - {name: duty, type: Outport, inputs: {u: duty}}\n";
  std::ofstream{folder / "top.yaml"} << "duet_model: 1\nname: top\nbase_period_us: 100\nblocks:\n"
                                        "  - {name: one, type: Constant, parameters: {value: 1}, outputs: {y: n}}\n"
                                        "  - {name: c, type: Subsystem, model: controller.yaml, inputs: {theta: n},"
                                        " outputs: {duty: d}}\n"
                                        "  - {name: pin, type: GpioOut, parameters: {pin: PA5}, inputs: {u: state}}\n";
  const std::string top = (folder / "top.yaml").string();
  const std::string controller = (folder / "controller.yaml").string();
  const Outcome outcome = run({"model", "check", top});
  std::filesystem::remove_all(folder);
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.err, controller +
                             ":8:81: error: input 'u' of block 'limit' reads signal 'thetta', which nothing drives "
                             "(did you mean 'theta'?)\n" +
                             top +
                             ":7:65: error: input 'u' of block 'pin' reads signal 'state', which nothing drives "
                             "(an output of a block, or of the subsystem's inputs, must drive it)\n" +
                             controller +
                             ":5:3: warning: parameter 'Kd' is not used (remove it, or use it in a block)\n");
}

}  // namespace
}  // namespace duet::cli
