// The import of each hand-written test model gives exactly the duet model committed for it in testing/expected/,
// compared as a whole: a change of the importer's output shows as a diff in review. A deliberate change is one command,
//   DUET_UPDATE_EXPECTED_MODELS=1 ctest --test-dir build/host -R ExpectedModels
// which rewrites the files in the source tree, and a `git diff` to read before committing them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <ostream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "duet/simulink_import/import.hpp"
#include "duet/simulink_import/import_options.hpp"
#include "duet/simulink_import/simulink_file.hpp"
#include "duet/simulink_import/slx_model.hpp"
#include "duet/support/text_file.hpp"
#include "testing/package_folder.hpp"

namespace duet::simulink_import {
namespace {

const std::filesystem::path testing_folder = DUET_SIMULINK_TESTING_DIR;

// One import of a test model, with the options its tests in import_test.cpp give it.
struct TestModel {
  std::string expected;  // the file in testing/expected: NAME.yaml a model, NAME.refused the problems of a refusal
  std::string source;    // in testing/: a folder of an .slx package's parts, or a file
  std::string slx_name;  // a folder's name as an .slx file; empty for a file
  std::vector<std::string> variable_files;  // in testing/
  ImportOptions options;
};

// gtest names a failing case by its file, not by the bytes of the struct.
void PrintTo(const TestModel& test, std::ostream* out) { *out << test.expected; }

// What an import gives, as one text: the model, or each problem on a line of its own.
std::string output_of(const ImportResult& imported) {
  if (imported.problems.empty()) return imported.model_text;
  std::string text;
  for (const std::string& problem : imported.problems) text += problem + "\n";
  return text;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

constexpr std::size_t context_lines = 3;  // around a difference, as diff -u shows it
constexpr std::size_t lines_shown = 12;   // of each side of a difference at most

// Whether the texts agree again from these lines on: for the next three lines, or up to both their ends.
bool agree_from(const std::vector<std::string>& before, std::size_t b, const std::vector<std::string>& after,
                std::size_t a) {
  for (std::size_t k = 0; k < context_lines; ++k) {
    const bool before_ends = b + k >= before.size();
    const bool after_ends = a + k >= after.size();
    if (before_ends || after_ends) return before_ends && after_ends;
    if (before[b + k] != after[a + k]) return false;
  }
  return true;
}

// The first difference as a unified diff's hunk: the lines that differ up to where the texts agree again (the
// fewest lines of both together), with three lines of context on either side.
std::string first_difference(const std::string& expected, const std::string& actual) {
  const std::vector<std::string> before = lines_of(expected);
  const std::vector<std::string> after = lines_of(actual);
  std::size_t same = 0;
  while (same < before.size() && same < after.size() && before[same] == after[same]) ++same;
  std::size_t removed = before.size() - same;
  std::size_t added = after.size() - same;
  for (std::size_t both = 1; both < removed + added; ++both) {
    bool found = false;
    for (std::size_t r = 0; r <= both && !found; ++r) {
      found = r <= removed && both - r <= added && agree_from(before, same + r, after, same + both - r);
      if (found) std::tie(removed, added) = std::pair{r, both - r};
    }
    if (found) break;
  }
  if (removed + added == 0) return "the texts differ only in the newline at their end\n";
  const std::size_t first = same - std::min(same, context_lines);
  const std::size_t after_context = std::min(context_lines, before.size() - same - removed);
  const auto count = [&](std::size_t changed) { return std::to_string(same - first + changed + after_context); };
  std::string hunk = "@@ -" + std::to_string(first + 1) + "," + count(removed) + " +" + std::to_string(first + 1) +
                     "," + count(added) + " @@\n";
  for (std::size_t line = first; line < same; ++line) hunk += " " + before[line] + "\n";
  const auto side = [&hunk](const std::vector<std::string>& lines, std::size_t from, std::size_t changed, char mark) {
    for (std::size_t line = from; line < from + std::min(changed, lines_shown); ++line)
      hunk += std::string{mark} + lines[line] + "\n";
    if (changed > lines_shown)
      hunk += std::string{mark} + "... (" + std::to_string(changed - lines_shown) + " lines more)\n";
  };
  side(before, same, removed, '-');
  side(after, same, added, '+');
  for (std::size_t line = same + removed; line < same + removed + after_context; ++line)
    hunk += " " + before[line] + "\n";
  return hunk;
}

class ExpectedModels : public ::testing::TestWithParam<TestModel> {};

TEST_P(ExpectedModels, TheImportGivesTheCommittedTextWhole) {
  const TestModel& test = GetParam();
  const std::filesystem::path source = testing_folder / test.source;
  auto model = test.slx_name.empty() ? read_simulink_file(source) : read_slx_model(parts_of(source), test.slx_name);
  ASSERT_TRUE(model) << model.error();
  ImportOptions options = test.options;
  std::vector<std::string> files;
  for (const std::string& file : test.variable_files) files.push_back((testing_folder / file).string());
  auto variables = read_variable_files(files);
  ASSERT_TRUE(variables) << variables.error();
  for (auto& [name, value] : variables.value()) options.variables.insert_or_assign(name, std::move(value));
  const ImportResult imported = import_simulink(model.value(), options);
  const std::string actual = output_of(imported);
  EXPECT_EQ(test.expected.ends_with(".yaml"), imported.problems.empty()) << actual;

  const std::filesystem::path expected_file = testing_folder / "expected" / test.expected;
  const char* update = std::getenv("DUET_UPDATE_EXPECTED_MODELS");
  if (update != nullptr && std::string{update} == "1") {
    std::ofstream out{expected_file, std::ios::binary};
    out << actual;
    ASSERT_TRUE(out.flush()) << "cannot write " << expected_file.string();
    return;
  }
  const auto expected = read_text_file(expected_file.string());
  ASSERT_TRUE(expected)
      << expected.error()
      << "\nwrite it with DUET_UPDATE_EXPECTED_MODELS=1 ctest --test-dir build/host -R ExpectedModels";
  EXPECT_TRUE(expected.value() == actual)
      << expected_file.string() << " is not what the import gives now:\n"
      << first_difference(expected.value(), actual)
      << "If the importer's output changed on purpose, rewrite the expected files with\n"
         "  DUET_UPDATE_EXPECTED_MODELS=1 ctest --test-dir build/host -R ExpectedModels\n"
         "and review the change with git diff before committing it.";
}

ImportOptions with_variables(std::initializer_list<std::pair<const char*, double>> values) {
  ImportOptions options;
  for (const auto& [name, value] : values) options.variables[name] = Value::scalar(value);
  return options;
}

ImportOptions with_interrupt(const std::string& path, InterruptTask task) {
  ImportOptions options;
  options.interrupts[path] = std::move(task);
  return options;
}

INSTANTIATE_TEST_SUITE_P(
    TestModels, ExpectedModels,
    ::testing::Values(
        TestModel{"slx_r2014a.yaml", "slx_r2014a", "scaled_lag.slx", {}, with_variables({{"pole", 0.5}})},
        TestModel{"slx_r2019b.yaml", "slx_r2019b", "tilt_loop.slx", {}, with_variables({{"Ts", 0.01}, {"Kp", 2}})},
        TestModel{"slx_r2021a.yaml", "slx_r2021a", "signal_chain.slx", {}, {}},
        // Refused: its PID link lacks values a saved link always has (Import.RefusesWhatItCannotProveEqual...).
        TestModel{"slx_r2022b.refused", "slx_r2022b", "pid_loop.slx", {}, {}},
        TestModel{
            "tilt_controller_r2022b.yaml", "tilt_controller_r2022b", "tilt_controller.slx", {"tilt_controller.m"}, {}},
        TestModel{"controller.yaml", "controller.mdl", {}, {"controller.m"}, {}},
        TestModel{"subsystems.yaml", "subsystems.mdl", {}, {}, with_interrupt("subsystems/ISR", {"TIM2", 3})},
        TestModel{"packaged_r2025b.yaml", "packaged_r2025b.mdl", {}, {}, {.base_period_us = 5000}},
        TestModel{"options_r2020a.yaml", "options_r2020a", "options.slx", {"options_r2020a.m"}, {}},
        TestModel{"pid_options.yaml", "pid_options.mdl", {}, {"pid_options.m"}, {}}),
    [](const ::testing::TestParamInfo<TestModel>& test) {
      return test.param.expected.substr(0, test.param.expected.find('.'));
    });

}  // namespace
}  // namespace duet::simulink_import
