#include "sched_command.hpp"

#include <CLI/CLI.hpp>

#include <fstream>
#include <map>
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

// Levels beyond what the core implements, or shared by several handlers: said before the report.
void check_levels(const sched::TaskSet& set, std::ostream& err, bool& fits) {
  const int groups = 1 << (set.core.priority_bits - set.core.sub_priority_bits);
  std::map<int, std::vector<std::string>> by_group;
  fits = true;
  for (const sched::Task& task : set.tasks) {
    by_group[task.priority->group].push_back(task.name);
    if (task.priority->group >= groups) fits = false;
  }
  if (!fits) {
    err << "duet sched: the priorities need group levels up to " << by_group.rbegin()->first << ", the core has "
        << groups << " (" << set.core.priority_bits - set.core.sub_priority_bits << " group bits)\n";
  }
}

ExitCode run_sched(const SchedOptions& options, Streams streams) {
  auto loaded = sched::load_task_file(options.file);
  if (!loaded) {
    streams.err << "duet sched: " << loaded.error() << '\n';
    return ExitCode::failure;
  }
  sched::TaskSet set = std::move(loaded).value();
  if (options.assign == "dm") {
    set =
        sched::with_priorities(set, sched::deadline_monotonic(set, options.first_level < 0 ? 1 : options.first_level));
  } else if (options.assign == "opa") {
    const auto priorities = sched::optimal_priorities(set, options.first_level < 0 ? 0 : options.first_level);
    if (!priorities) {
      streams.err << "duet sched: no fixed-priority order meets every deadline (Audsley's assignment found none)\n";
      return ExitCode::failure;
    }
    set = sched::with_priorities(set, *priorities);
  }
  auto analysis = sched::analyse(set);
  if (!analysis) {
    streams.err << "duet sched: " << options.file << ": " << analysis.error() << " (--assign dm or opa)\n";
    return ExitCode::failure;
  }
  bool fits = true;
  check_levels(set, streams.err, fits);
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
  return analysis.value().schedulable() && fits ? ExitCode::success : ExitCode::failure;
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
