#include "gen_command.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>

#include "checked_model.hpp"
#include "duet/model/generate.hpp"
#include "duet/support/text_file.hpp"

namespace duet::cli {
namespace {

struct GenOptions {
  std::string file;
  std::string output = ".";
};

ExitCode run_gen(const GenOptions& options, Streams streams) {
  const auto checked = load_checked_model(options.file, streams.err);
  if (!checked) return ExitCode::failure;
  for (const model::Diagnostic& warning : model::precision_warnings(checked->program)) {
    streams.err << model::format(options.file, warning) << '\n';
  }
  std::error_code error;
  std::filesystem::create_directories(options.output, error);
  if (error) {
    streams.err << "duet gen: cannot create " << options.output << ": " << error.message() << '\n';
    return ExitCode::failure;
  }
  // The model's folder as the CMake fragment reaches it from the output folder (for Code blocks' headers).
  const std::filesystem::path model_folder =
      std::filesystem::weakly_canonical(std::filesystem::absolute(options.file)).parent_path();
  const std::string relative =
      model_folder.lexically_relative(std::filesystem::weakly_canonical(options.output)).generic_string();
  auto files = model::generate(checked->program, std::filesystem::path{options.file}.filename().string(),
                               relative.empty() ? "." : relative);
  if (!files) {
    streams.err << "duet gen: " << options.file << ": " << files.error() << '\n';
    return ExitCode::failure;
  }
  for (const model::GeneratedFile& file : files.value()) {
    const std::filesystem::path path = std::filesystem::path{options.output} / file.name;
    // Unchanged files keep their time stamps, so that builds do not redo them.
    if (const auto existing = read_text_file(path.string()); existing.ok() && existing.value() == file.text) continue;
    std::ofstream out{path, std::ios::binary};
    out << file.text;
    if (!out) {
      streams.err << "duet gen: cannot write " << path.string() << '\n';
      return ExitCode::failure;
    }
  }
  streams.out << "generated " << checked->model->name << " into " << options.output << ":";
  for (const model::GeneratedFile& file : files.value()) streams.out << ' ' << file.name;
  streams.out << '\n';
  return ExitCode::success;
}

}  // namespace

Action define_gen_command(CLI::App& command) {
  auto options = std::make_shared<GenOptions>();
  command.add_option("model", options->file, "The model file (docs/MODELS.md)")->required();
  command.add_option("-o,--output", options->output, "The folder to write into (created if missing)")
      ->capture_default_str();
  return [options](Streams streams) { return run_gen(*options, streams); };
}

}  // namespace duet::cli
