// What generated code does when the model starts (initialize()): states set to their initial values and constant
// outputs computed, from the parameters where the model says so.
#include <gtest/gtest.h>

#include <string>

#include "duet/model/generate.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"

namespace duet::model {
namespace {

// The body of initialize() in the generated .cpp of `text`, in either storage.
std::string initialize_body(const std::string& text, Storage storage) {
  const auto model = parse_model(text, "m.yaml");
  if (!model.ok()) return "(does not read: " + model.error() + ")";
  const ProgramBuild build = build_program(model.value());
  if (!build.program) return "(does not build)";
  const auto files = generate(*build.program, "m.yaml", "..", storage);
  if (!files.ok()) return "(does not generate: " + files.error() + ")";
  for (const GeneratedFile& file : files.value()) {
    if (file.name != "m.cpp") continue;
    const std::size_t begin = file.text.find("void initialize() {\n");
    return file.text.substr(begin, file.text.find("\n}\n", begin) - begin);
  }
  return "(no m.cpp)";
}

// An integrator whose initial value is a parameter: its reset reads the parameters, which initialize() must then have
// in hand (it had not, and the code did not compile).
TEST(GeneratedStart, AStateWhoseInitialValueIsAParameterReadsItFromThePageInUse) {
  const std::string model =
      "duet_model: 1\nname: m\nbase_period_us: 1000\n"
      "parameters:\n"
      "  initial: {value: 2, type: single}\n"
      "blocks:\n"
      "  - {name: one, type: Constant, parameters: {value: 1, type: single}, outputs: {y: u}}\n"
      "  - {name: sum, type: DiscreteIntegrator, parameters: {initial: initial}, inputs: {u: u}, outputs: {y: y}}\n";
  for (const Storage storage : {Storage::global, Storage::per_instance}) {
    const std::string body = initialize_body(model, storage);
    const std::size_t page = body.find("const Parameters& p = parameters_in_use();");
    const std::size_t use = body.find("= p.initial;");
    ASSERT_NE(use, std::string::npos) << body;
    EXPECT_LT(page, use) << body;
  }
}

}  // namespace
}  // namespace duet::model
