// The precision policy (docs/MODELS.md, "Precision"): where a model computes in double without saying so, duet gen
// warns once per place double starts, at that place.
#include <gtest/gtest.h>

#include <string>

#include "duet/model/generate.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"

namespace duet::model {
namespace {

// The precision warnings of a model, formatted, one per line.
std::string warnings_of(const std::string& text) {
  const auto model = parse_model(text, "m.yaml");
  if (!model.ok()) return "(does not read: " + model.error() + ")";
  const ProgramBuild build = build_program(model.value());
  if (!build.program) {
    std::string errors = "(does not build)\n";
    for (const Diagnostic& diagnostic : build.diagnostics) errors += format("m.yaml", diagnostic) + "\n";
    return errors;
  }
  std::string lines;
  for (const Diagnostic& diagnostic : precision_warnings(*build.program)) lines += format("m.yaml", diagnostic) + "\n";
  return lines;
}

constexpr const char* header = "duet_model: 1\nname: m\nbase_period_us: 100\n";

TEST(Precision, AParameterWithoutATypeIsDoubleAndSaysSo) {
  EXPECT_EQ(warnings_of(std::string{header} +
                        "parameters:\n"
                        "  k: {value: 2}\n"
                        "  s: {value: 2, type: single}\n"
                        "blocks:\n"
                        "  - {name: c, type: Constant, parameters: {value: 1, type: single}, outputs: {y: x}}\n"
                        "  - {name: g, type: Gain, parameters: {k: s}, inputs: {u: x}, outputs: {y: y}}\n"
                        "  - {name: use_k, type: Constant, parameters: {value: k}, outputs: {y: kk}}\n"),
            "m.yaml:5:3: warning: parameter 'k' is double precision, which the Cortex-M4 computes in software (give "
            "it 'type: single', or say 'precision: double' at the top of the model)\n");
}

// A literal Constant is double unless typed: the warning names it, and not the Gain that computes from it.
TEST(Precision, WhereDoubleStartsNotWhereItFlows) {
  EXPECT_EQ(
      warnings_of(std::string{header} +
                  "blocks:\n"
                  "  - {name: c, type: Constant, parameters: {value: 1}, outputs: {y: x}}\n"
                  "  - {name: g, type: Gain, parameters: {k: 3}, inputs: {u: x}, outputs: {y: y}}\n"
                  "  - {name: f, type: Constant, parameters: {value: 1, type: single}, outputs: {y: z}}\n"
                  "  - {name: widen, type: Convert, parameters: {type: double}, inputs: {u: z}, outputs: {y: w}}\n"),
      "m.yaml:5:5: warning: block 'c' computes in double precision, which the Cortex-M4 does in software (give "
      "its type as single, or say 'precision: double' at the top of the model)\n"
      "m.yaml:8:5: warning: block 'widen' computes in double precision, which the Cortex-M4 does in software "
      "(give its type as single, or say 'precision: double' at the top of the model)\n");
}

TEST(Precision, AModelThatAsksForDoubleGetsNoWarning) {
  EXPECT_EQ(
      warnings_of(std::string{header} + "precision: double\n"
                                        "parameters:\n"
                                        "  k: {value: 2}\n"
                                        "blocks:\n"
                                        "  - {name: c, type: Constant, parameters: {value: k}, outputs: {y: x}}\n"
                                        "  - {name: d, type: Constant, parameters: {value: 1}, outputs: {y: z}}\n"),
      "");
}

TEST(Precision, TheRobotIsSinglePrecisionThroughout) {
  const auto model = load_model(DUET_SOURCE_DIR "/apps/balbot/balbot.yaml");
  ASSERT_TRUE(model.ok()) << model.error();
  const ProgramBuild build = build_program(model.value());
  ASSERT_TRUE(build.program);
  EXPECT_TRUE(precision_warnings(*build.program).empty());
}

TEST(Precision, OnlySingleOrDouble) {
  EXPECT_EQ(
      warnings_of(std::string{header} + "precision: quad\nblocks:\n"),
      "(does not read: m.yaml:4:12: error: 'precision' is single or double (double: the model computes in double on "
      "purpose))");
}

}  // namespace
}  // namespace duet::model
