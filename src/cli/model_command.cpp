#include "model_command.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "checked_model.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/rates.hpp"
#include "duet/model/render.hpp"
#include "duet/model/task_set_file.hpp"
#include "firmware_console.hpp"

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

// NAME=NUMBER words into a map; false, with the word named, if one is not.
template <typename Key>
bool assignments(const std::vector<std::string>& given, std::map<Key, double>& into, std::string_view what,
                 std::ostream& err) {
  for (const std::string& assignment : given) {
    const auto equals = assignment.find('=');
    double value = 0;
    const char* number = equals == std::string::npos ? nullptr : assignment.c_str() + equals + 1;
    char* end = nullptr;
    if (number != nullptr) value = std::strtod(number, &end);
    Key key{};
    bool key_read = equals != std::string::npos;
    if constexpr (std::is_same_v<Key, std::string>) {
      if (key_read) key = assignment.substr(0, equals);
    } else if (key_read) {
      const auto [at, error] = std::from_chars(assignment.data(), assignment.data() + equals, key);
      key_read = error == std::errc{} && at == assignment.data() + equals && equals > 0;
    }
    if (!key_read || number == nullptr || end == number || *end != '\0') {
      err << "duet model tasks: '" << assignment << "' is not " << what << '\n';
      return false;
    }
    into[key] = value;
  }
  return true;
}

// Microseconds rounded up to the picosecond, the task file's finest unit: a bound may grow, never shrink.
double microseconds_up(std::uint64_t cycles, double cycles_per_us) {
  return std::ceil(static_cast<double>(cycles) / cycles_per_us * 1e6) / 1e6;
}

// The execution times and sections a firmware's console reported (its latest duet-task and duet-section lines), in
// microseconds at `cycles_per_us`. A task that never ran has no time to give.
Status read_measured(const std::string& console, double cycles_per_us, std::map<std::string, double>& wcet_us,
                     std::map<int, double>& sections_us) {
  std::ifstream in{console};
  if (!in) return Failure{"cannot read the console file '" + console + "'"};
  if (!(cycles_per_us > 0))
    return Failure{"--measured needs --cycles-per-us above 0 (the rate of the cycles it reports)"};
  FirmwareReport report;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const ConsoleLine parsed = parse_console_line(line);
    if (const auto* malformed = std::get_if<MalformedLine>(&parsed))
      return Failure{console + ":" + std::to_string(number) + ": " + malformed->problem};
    take(report, parsed);
  }
  if (report.tasks.empty()) return Failure{console + ": no duet-task line (a firmware's console, docs/LINK.md)"};
  for (const FirmwareTask& task : report.tasks) {
    if (task.name.empty() || task.activations == 0) continue;
    // The console names tasks as the task table does ("rate_1", "EXTI8"); the task file as their functions do.
    const std::string name = (task.name.starts_with("rate_") ? "step_" : "task_") + task.name;
    wcet_us[name] = microseconds_up(task.max_cycles, cycles_per_us);
  }
  for (const auto& [ceiling, longest] : report.sections)
    sections_us[static_cast<int>(ceiling)] = microseconds_up(longest, cycles_per_us);
  return done();
}

struct TaskTimesGiven {
  std::vector<std::string> wcet;
  std::vector<std::string> interarrival;
  std::vector<std::string> sections;
  std::string measured;
  double cycles_per_us = 0;
};

// The tasks as a task file for `duet sched`, with the times the model cannot know measured on the target (a console)
// or given as NAME=MICROSECONDS, which win.
ExitCode tasks(const std::string& file, const TaskTimesGiven& given, Streams streams) {
  const auto checked = load_checked_model(file, streams.err);
  if (!checked) return ExitCode::failure;
  std::map<std::string, double> wcet_us;
  std::map<std::string, double> interarrival_us;
  std::map<int, double> sections_us;
  if (!given.measured.empty()) {
    if (Status read = read_measured(given.measured, given.cycles_per_us, wcet_us, sections_us); !read) {
      streams.err << "duet model tasks: " << read.error() << '\n';
      return ExitCode::failure;
    }
  }
  if (!assignments(given.wcet, wcet_us, "TASK=MICROSECONDS", streams.err) ||
      !assignments(given.interarrival, interarrival_us, "TASK=MICROSECONDS", streams.err) ||
      !assignments(given.sections, sections_us, "GROUP=MICROSECONDS", streams.err)) {
    return ExitCode::failure;
  }
  auto text = model::task_set_file(checked->program, wcet_us, interarrival_us, sections_us);
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
  TaskTimesGiven times;
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
  tasks_command->add_option("--wcet", options->times.wcet, "TASK=US: a task's measured execution time (every task)");
  tasks_command->add_option("--interarrival", options->times.interarrival,
                            "TASK=US: the shortest time between an interrupt task's triggers");
  tasks_command->add_option("--section", options->times.sections,
                            "GROUP=US: the longest critical section measured at a priority ceiling (blocking)");
  tasks_command->add_option("--measured", options->times.measured,
                            "A firmware's console (duet pil --console): each task's longest time and each ceiling's "
                            "longest section, as the executive measured them; --wcet and --section win");
  tasks_command->add_option("--cycles-per-us", options->times.cycles_per_us,
                            "The rate of the cycles the console reports, per microsecond (with --measured)");
  return [options, render_command, tasks_command](Streams streams) {
    if (render_command->parsed()) return render(options->file, options->output, options->dot, streams);
    if (tasks_command->parsed()) return tasks(options->file, options->times, streams);
    return check(options->file, options->json, streams);
  };
}

}  // namespace duet::cli
