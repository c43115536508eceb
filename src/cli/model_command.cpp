#include "model_command.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "checked_model.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/rates.hpp"
#include "duet/model/render.hpp"
#include "duet/model/task_set_file.hpp"

namespace duet::cli {
namespace {

std::string join(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "(no blocks)" : text;
}

// What a diagram of the model shows, counted from the file: the blocks it writes (subsystems apart) and, per system,
// each signal named there (a block's port, a trigger or enable, a subsystem's port seen from inside) once.
struct Drawn {
  std::size_t blocks = 0;
  std::size_t subsystems = 0;
  std::size_t wires = 0;
};

void count_drawn(const std::vector<model::Block>& blocks, const model::Block* owner, Drawn& drawn) {
  std::set<std::string> signals;
  if (owner != nullptr) {
    for (const model::Connection& port : owner->inputs) signals.insert(port.port);
    for (const model::Connection& port : owner->outputs) signals.insert(port.port);
  }
  for (const model::Block& block : blocks) {
    for (const model::Connection& connection : block.inputs) signals.insert(connection.signal);
    for (const model::Connection& connection : block.outputs) signals.insert(connection.signal);
    if (block.trigger.kind == model::Trigger::Kind::edge) signals.insert(block.trigger.signal);
    if (!block.enable.empty()) signals.insert(block.enable);
    if (block.type == "Subsystem") {
      ++drawn.subsystems;
      count_drawn(block.blocks, &block, drawn);
    } else {
      ++drawn.blocks;
    }
  }
  drawn.wires += signals.size();
}

// For scripts and the studio's browser tests: what the diagram must show, and the tasks.
std::string check_json(const model::Model& source, const model::RateAnalysis& rates) {
  Drawn drawn;
  count_drawn(source.blocks, nullptr, drawn);
  nlohmann::json tasks = nlohmann::json::array();
  for (const model::Task& task : rates.tasks) tasks.push_back({{"name", task.name}, {"blocks", task.blocks.size()}});
  return nlohmann::json{{"name", source.name},
                        {"blocks", drawn.blocks},
                        {"subsystems", drawn.subsystems},
                        {"wires", drawn.wires},
                        {"scheduled_blocks", rates.block_rates.size()},
                        {"tasks", tasks}}
      .dump();
}

// Diagnostics on standard error; with none that is an error, the task table with each task's blocks in execution
// order on standard output (or, with `json`, the counts of check_json).
ExitCode check(const std::string& file, bool json, Streams streams) {
  const auto checked = load_checked_model(file, streams.err);  // validation, rates, then types and sizes
  if (!checked) return ExitCode::failure;
  const model::Model& source = *checked->model;
  const model::RateAnalysis rates = model::analyse_rates(source);
  if (json) {
    streams.out << check_json(source, rates) << '\n';
    return ExitCode::success;
  }
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

// The tasks as a task file for `duet sched`, with the times the model cannot know given as NAME=MICROSECONDS.
ExitCode tasks(const std::string& file, const std::vector<std::string>& wcet,
               const std::vector<std::string>& interarrival, Streams streams) {
  const auto checked = load_checked_model(file, streams.err);
  if (!checked) return ExitCode::failure;
  std::map<std::string, double> wcet_us;
  std::map<std::string, double> interarrival_us;
  for (const auto& [given, into] : {std::pair{&wcet, &wcet_us}, std::pair{&interarrival, &interarrival_us}}) {
    for (const std::string& assignment : *given) {
      const auto equals = assignment.find('=');
      double value = 0;
      const char* number = equals == std::string::npos ? nullptr : assignment.c_str() + equals + 1;
      char* end = nullptr;
      if (number != nullptr) value = std::strtod(number, &end);
      if (number == nullptr || end == number || *end != '\0') {
        streams.err << "duet model tasks: '" << assignment << "' is not TASK=MICROSECONDS\n";
        return ExitCode::failure;
      }
      (*into)[assignment.substr(0, equals)] = value;
    }
  }
  auto text = model::task_set_file(checked->program, wcet_us, interarrival_us);
  if (!text) {
    streams.err << "duet model tasks: " << text.error() << '\n';
    return ExitCode::failure;
  }
  streams.out << text.value();
  return ExitCode::success;
}

struct ModelOptions {
  std::string file;
  std::string output;
  bool dot = false;
  bool json = false;
  std::vector<std::string> wcet;
  std::vector<std::string> interarrival;
};

}  // namespace

Action define_model_command(CLI::App& command) {
  auto options = std::make_shared<ModelOptions>();
  command.require_subcommand(1);
  CLI::App* check_command = command.add_subcommand("check", "Validate a model file and list its tasks");
  check_command->add_option("file", options->file, "The model file (docs/MODELS.md)")->required();
  check_command->add_flag("--json", options->json,
                          "Print what its diagram shows (blocks, subsystems, wires) and its tasks as JSON");
  CLI::App* render_command = command.add_subcommand("render", "Draw the block diagram as SVG (with Graphviz)");
  render_command->add_option("file", options->file, "The model file")->required();
  render_command->add_option("-o,--output", options->output, "The SVG file (default: the model's name with .svg)");
  render_command->add_flag("--dot", options->dot, "Print the diagram in Graphviz's language instead");
  CLI::App* tasks_command =
      command.add_subcommand("tasks", "Print the model's tasks as a task file for duet sched (docs/SCHEDULING.md)");
  tasks_command->add_option("file", options->file, "The model file")->required();
  tasks_command->add_option("--wcet", options->wcet, "TASK=US: a task's measured execution time (every task)");
  tasks_command->add_option("--interarrival", options->interarrival,
                            "TASK=US: the shortest time between an interrupt task's triggers");
  return [options, render_command, tasks_command](Streams streams) {
    if (render_command->parsed()) return render(options->file, options->output, options->dot, streams);
    if (tasks_command->parsed()) return tasks(options->file, options->wcet, options->interarrival, streams);
    return check(options->file, options->json, streams);
  };
}

}  // namespace duet::cli
