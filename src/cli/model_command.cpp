#include "model_command.hpp"

#include <CLI/CLI.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "checked_model.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/rates.hpp"
#include "duet/model/render.hpp"

namespace duet::cli {
namespace {

std::string join(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "(no blocks)" : text;
}

// Diagnostics on standard error; with none that is an error, the task table with each task's blocks in execution
// order on standard output.
ExitCode check(const std::string& file, Streams streams) {
  const auto checked = load_checked_model(file, streams.err);  // validation, rates, then types and sizes
  if (!checked) return ExitCode::failure;
  const model::Model& source = *checked->model;
  const model::RateAnalysis rates = model::analyse_rates(source);
  streams.out << source.name << ": " << rates.block_rates.size() << " blocks, " << rates.tasks.size() << " tasks\n";
  for (const model::Task& task : rates.tasks) {
    streams.out << "  " << task.name << ": ";
    if (task.rate.kind == model::Rate::Kind::periodic) {
      streams.out << "every " << task.period_us << " us";
    } else {
      streams.out << "interrupt " << task.rate.interrupt << ", priority "
                  << (task.priority ? std::to_string(*task.priority) : std::string{"auto"});
    }
    streams.out << ": " << join(task.blocks) << '\n';
  }
  if (!rates.constant_blocks.empty())
    streams.out << "  once, at initialisation: " << join(rates.constant_blocks) << '\n';
  return ExitCode::success;
}

// The diagram as SVG through Graphviz's dot (or the DOT text itself): `output` defaults to the model file's name
// with .svg.
ExitCode render(const std::string& file, std::string output, bool dot_only, Streams streams) {
  auto model = model::load_model(file);
  if (!model) {
    streams.err << model.error() << '\n';
    return ExitCode::failure;
  }
  const std::string dot = model::to_dot(model.value());
  if (dot_only) {
    streams.out << dot;
    return ExitCode::success;
  }
  if (output.empty()) output = std::filesystem::path{file}.replace_extension(".svg").string();
  const std::filesystem::path source =
      std::filesystem::temp_directory_path() / ("duet_render_" + std::to_string(::getpid()) + ".dot");
  std::ofstream{source} << dot;
  std::vector<std::string> arguments{"dot", "-Tsvg", source.string(), "-o", output};
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawned = posix_spawnp(&child, "dot", nullptr, nullptr, argv.data(), environ);
  int status = 0;
  if (spawned == 0) waitpid(child, &status, 0);
  std::filesystem::remove(source);
  if (spawned != 0) {
    streams.err << "duet model render: Graphviz's dot was not found (scripts/setup.sh installs graphviz; --dot "
                   "prints the diagram's DOT text instead)\n";
    return ExitCode::failure;
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    streams.err << "duet model render: dot failed on the diagram of " << file << '\n';
    return ExitCode::failure;
  }
  streams.out << "wrote " << output << '\n';
  return ExitCode::success;
}

struct ModelOptions {
  std::string file;
  std::string output;
  bool dot = false;
};

}  // namespace

Action define_model_command(CLI::App& command) {
  auto options = std::make_shared<ModelOptions>();
  command.require_subcommand(1);
  CLI::App* check_command = command.add_subcommand("check", "Validate a model file and list its tasks");
  check_command->add_option("file", options->file, "The model file (docs/MODELS.md)")->required();
  CLI::App* render_command = command.add_subcommand("render", "Draw the block diagram as SVG (with Graphviz)");
  render_command->add_option("file", options->file, "The model file")->required();
  render_command->add_option("-o,--output", options->output, "The SVG file (default: the model's name with .svg)");
  render_command->add_flag("--dot", options->dot, "Print the diagram in Graphviz's language instead");
  return [options, render_command](Streams streams) {
    if (render_command->parsed()) return render(options->file, options->output, options->dot, streams);
    return check(options->file, streams);
  };
}

}  // namespace duet::cli
