// The generated code committed beside each example is what duet gen makes of the model now, byte for byte.
#include <gtest/gtest.h>

#include "duet/model/generate.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/support/text_file.hpp"
#include "examples.hpp"

namespace duet::model {
namespace {

class Golden : public testing::TestWithParam<std::string> {};

TEST_P(Golden, CommittedCodeIsWhatTheGeneratorMakes) {
  const std::string& name = GetParam();
  auto model = load_model(example_file(name));
  ASSERT_TRUE(model.ok()) << model.error();
  const ProgramBuild build = build_program(model.value());
  ASSERT_TRUE(build.program.has_value());
  auto files = generate(*build.program, name + ".yaml");
  ASSERT_TRUE(files.ok()) << files.error();
  for (const GeneratedFile& file : files.value()) {
    auto committed = read_text_file(generated_folder(name) + "/" + file.name);
    ASSERT_TRUE(committed.ok()) << committed.error();
    EXPECT_TRUE(committed.value() == file.text)
        << file.name << " differs from what duet gen makes now; regenerate it with\n  duet gen apps/" << name << "/"
        << name << ".yaml -o apps/" << name << "/generated";
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, Golden, testing::ValuesIn(example_models),
                         [](const testing::TestParamInfo<std::string>& parameter) { return parameter.param; });

}  // namespace
}  // namespace duet::model
