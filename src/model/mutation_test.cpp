// Bad model files never crash the tools: the example models, mutated at random (a fixed seed, so every run is the
// same), go through reading, checking, generation and a short simulation; each either works or says where it failed.
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "duet/model/generate.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/support/text_file.hpp"

namespace duet::model {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in{text};
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// One to three edits of the kinds a hurried person makes: a line lost, doubled or moved, a character changed, the
// file cut short.
std::string mutated(const std::vector<std::string>& original, std::mt19937& random) {
  std::vector<std::string> lines = original;
  const auto pick = [&random](std::size_t count) {
    return std::uniform_int_distribution<std::size_t>{0, count - 1}(random);
  };
  constexpr std::string_view replacements = " :{}[],-0123456789abcuyxAZ_\"'\n#";
  const std::size_t edits = 1 + pick(3);
  for (std::size_t edit = 0; edit < edits && !lines.empty(); ++edit) {
    const std::size_t at = pick(lines.size());
    switch (pick(5)) {
      case 0: lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(at)); break;
      case 1: lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(at), lines[at]); break;
      case 2: std::swap(lines[at], lines[pick(lines.size())]); break;
      case 3:
        if (!lines[at].empty()) lines[at][pick(lines[at].size())] = replacements[pick(replacements.size())];
        break;
      default: lines.resize(at + 1); break;
    }
  }
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

class Mutated : public ::testing::TestWithParam<std::string> {};

TEST_P(Mutated, ModelsWorkOrSayWhereTheyFail) {
  const std::string folder = std::string{DUET_SOURCE_DIR} + "/apps/" + GetParam() + "/";
  const auto original = read_text_file(folder + GetParam() + ".yaml");
  ASSERT_TRUE(original.ok());
  const std::vector<std::string> lines = lines_of(original.value());
  std::mt19937 random{7};
  std::size_t refused = 0;
  std::size_t generated = 0;
  for (int round = 0; round < 300; ++round) {
    const std::string text = mutated(lines, random);
    // Beside the original, so that a Code block's header is found.
    const auto model = parse_model(text, folder + "mutated.yaml");
    if (!model.ok()) {
      EXPECT_EQ(model.error().rfind(folder + "mutated.yaml:", 0), 0U) << model.error();
      ++refused;
      continue;
    }
    const ProgramBuild build = build_program(model.value());
    for (const Diagnostic& diagnostic : build.diagnostics) {
      EXPECT_GT(diagnostic.location.line, 0) << diagnostic.message;
      EXPECT_FALSE(diagnostic.message.empty());
    }
    if (!build.program) {
      ++refused;
      continue;
    }
    const auto files = generate(*build.program, "mutated.yaml");
    if (files.ok()) ++generated;
    const bool user_code = std::any_of(build.program->blocks.begin(), build.program->blocks.end(),
                                       [](const ProgramBlock& block) { return block.block->code.has_value(); });
    if (user_code) continue;  // compiling it 150 times is the compiler's test, not ours
    plant::Loopback plant;
    const auto simulated = simulate(*build.program, plant, {0.01, {}, {}});
    EXPECT_TRUE(simulated.ok() || !simulated.error().empty());
  }
  // The mutations were of every kind: some broke the file, some left a model that still works.
  EXPECT_GT(refused, 0U);
  EXPECT_GT(generated, 0U);
}

INSTANTIATE_TEST_SUITE_P(Examples, Mutated,
                         ::testing::Values("step_time", "transfer_test", "pid_demo", "thermostat", "block_tour",
                                           "balbot"));

}  // namespace
}  // namespace duet::model
