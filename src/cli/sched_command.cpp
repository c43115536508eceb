#include "sched_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <fstream>
#include <memory>
#include <ostream>
#include <string>

#include "duet/sched/priority_assignment.hpp"
#include "duet/sched/report.hpp"
#include "duet/sched/response_time.hpp"
#include "duet/sched/task_file.hpp"

namespace duet::cli {
namespace {

struct SchedOptions {
  std::string file;
  std::string assign = "keep";
  int first_level = -1;  // -1: the method's own (1 for dm, as the thesis; 0 for opa)
  bool json = false;
  std::string svg;
};

// More group priorities than the core implements: share levels where deadlines allow, and say which.
Result<sched::TaskSet> fit_levels(sched::TaskSet set, int first_level, std::ostream& err) {
  const int groups = 1 << (set.core.priority_bits - set.core.sub_priority_bits);
  int most = 0;
  for (const sched::Task& task : set.tasks) most = std::max(most, task.priority->group);
  if (most < groups) return set;
  const int levels = groups - first_level;
  const auto fit = levels > 0 ? sched::fit_to_levels(set, levels, first_level) : std::nullopt;
  if (!fit) {
    return Failure{"the priorities need group levels up to " + std::to_string(most) + ", the core has " +
                   std::to_string(groups) + ", and no sharing of levels keeps every deadline"};
  }
  err << "duet sched: the core has " << groups << " group levels; sharing levels to fit:\n";
  for (const auto& tasks : fit->shared) {
    err << "  level " << fit->priorities[tasks.front()].group << ":";
    for (std::size_t i : tasks) err << " '" << set.tasks[i].name << "'";
    err << '\n';
  }
  return sched::with_priorities(std::move(set), fit->priorities);
}

ExitCode run_sched(const SchedOptions& options, Streams streams) {
  auto loaded = sched::load_task_file(options.file);
  if (!loaded) {
    streams.err << "duet sched: " << loaded.error() << '\n';
    return ExitCode::failure;
  }
  sched::TaskSet set = std::move(loaded).value();
  const int first_level = options.first_level >= 0 ? options.first_level : options.assign == "dm" ? 1 : 0;
  if (options.assign == "dm") {
    set = sched::with_priorities(set, sched::deadline_monotonic(set, first_level));
  } else if (options.assign == "opa") {
    const auto priorities = sched::optimal_priorities(set, first_level);
    if (!priorities) {
      streams.err << "duet sched: no fixed-priority order meets every deadline (Audsley's assignment found none)\n";
      return ExitCode::failure;
    }
    set = sched::with_priorities(set, *priorities);
  }
  for (const sched::Task& task : set.tasks) {
    if (!task.priority) {
      streams.err << "duet sched: " << options.file << ": task '" << task.name
                  << "' has no priority: give it one, or --assign dm or opa\n";
      return ExitCode::failure;
    }
  }
  auto fitted = fit_levels(std::move(set), first_level, streams.err);
  if (!fitted) {
    streams.err << "duet sched: " << fitted.error() << '\n';
    return ExitCode::failure;
  }
  set = std::move(fitted).value();
  auto analysis = sched::analyse(set);
  if (!analysis) {
    streams.err << "duet sched: " << analysis.error() << '\n';
    return ExitCode::failure;
  }
  streams.out << (options.json ? sched::json_report(set, analysis.value()) + "\n"
                               : sched::text_report(set, analysis.value()));
  if (!options.svg.empty()) {
    std::ofstream svg{options.svg};
    svg << sched::timeline_svg(set, analysis.value());
    if (!svg) {
      streams.err << "duet sched: cannot write " << options.svg << '\n';
      return ExitCode::failure;
    }
  }
  return analysis.value().schedulable() ? ExitCode::success : ExitCode::failure;
}

}  // namespace

Action define_sched_command(CLI::App& command) {
  auto options = std::make_shared<SchedOptions>();
  command.add_option("file", options->file, "The task-set file (YAML, docs/SCHEDULING.md)")->required();
  command
      .add_option("--assign", options->assign,
                  "keep: the file's priorities; dm: the thesis' deadline-monotonic rules; opa: Audsley's optimal "
                  "assignment")
      ->check(CLI::IsMember({"keep", "dm", "opa"}));
  command.add_option("--first-level", options->first_level, "The most urgent group priority to assign (dm: 1, opa: 0)")
      ->check(CLI::Range(0, 255));
  command.add_flag("--json", options->json, "Print JSON for scripts");
  command.add_option("--svg", options->svg, "Write the worst-case timeline to this SVG file");
  return [options](Streams streams) { return run_sched(*options, streams); };
}

}  // namespace duet::cli
