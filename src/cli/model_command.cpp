#include "model_command.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "duet/model/model_file.hpp"
#include "duet/model/rates.hpp"
#include "duet/model/validate.hpp"

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
  auto model = model::load_model(file);
  if (!model) {
    streams.err << model.error() << '\n';
    return ExitCode::failure;
  }
  const std::vector<model::Diagnostic> diagnostics = model::validate(model.value());
  for (const model::Diagnostic& diagnostic : diagnostics) streams.err << model::format(file, diagnostic) << '\n';
  if (model::has_errors(diagnostics)) return ExitCode::failure;
  const model::RateAnalysis rates = model::analyse_rates(model.value());
  streams.out << model.value().name << ": " << rates.block_rates.size() << " blocks, " << rates.tasks.size()
              << " tasks\n";
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

}  // namespace

Action define_model_command(CLI::App& command) {
  auto file = std::make_shared<std::string>();
  command.require_subcommand(1);
  CLI::App* check_command = command.add_subcommand("check", "Validate a model file and list its tasks");
  check_command->add_option("file", *file, "The model file (docs/MODELS.md)")->required();
  return [file](Streams streams) { return check(*file, streams); };
}

}  // namespace duet::cli
