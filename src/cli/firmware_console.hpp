#pragma once
// What the firmware under `duet pil` says on its console (the emulated board's UART3), line by line:
//
//   duet-status time_s=1.000 ticks=1000 busy_ppm=123456 overruns=0      every second of model time, cumulative
//   duet-task index=0 name=step_rate_1 activations=1000 overruns=0 min_cycles=120 mean_cycles=130 max_cycles=150
//                                                                        one per task, after each duet-status
//   duet-lost xcp_responses=0 daq_samples=0 telemetry=0                  with each duet-status, cumulative: what the
//                                                                        firmware's channels dropped, by name
//   duet-section ceiling=9 longest_cycles=40                             after the tasks, one per priority ceiling
//                                                                        (its group) where a section was measured
//   duet-end reason=final_tick ticks=10000 overruns=0                    once, when the firmware stops by itself
//
// Fields are KEY=VALUE words separated by spaces, in any order; keys a line does not know are skipped, so that the
// firmware may say more. Any other line is free text. Cycles are ticks of the board's 25 MHz timer.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace duet::cli {

struct FirmwareStatus {
  double time_s = 0;  // model time
  std::uint64_t ticks = 0;
  std::uint64_t busy_ppm = 0;  // the share of time the core was busy, in millionths
  std::uint64_t overruns = 0;
};

struct FirmwareTask {
  std::uint64_t index = 0;
  std::string name;
  std::uint64_t activations = 0;
  std::uint64_t overruns = 0;
  std::uint64_t min_cycles = 0;
  std::uint64_t mean_cycles = 0;
  std::uint64_t max_cycles = 0;
};

// The longest critical section measured at a priority ceiling (docs/EXECUTIVE.md, "Priority ceilings").
struct FirmwareSection {
  std::uint64_t ceiling = 0;  // the group, 0 to 15
  std::uint64_t longest_cycles = 0;
};

struct FirmwareEnd {
  std::string reason;  // final_tick, ...
  std::uint64_t ticks = 0;
  std::uint64_t overruns = 0;
};

// Counts of what was lost, each under the firmware's name for it, in the order the line gives them.
struct FirmwareLosses {
  std::vector<std::pair<std::string, std::uint64_t>> counts;
};

struct ConsoleText {
  std::string text;
};

// A duet-status, duet-task or duet-end line that does not say what it must: a bug in the firmware worth telling.
struct MalformedLine {
  std::string problem;  // "duet-task: no 'name'"
};

using ConsoleLine = std::variant<FirmwareStatus, FirmwareTask, FirmwareSection, FirmwareEnd, FirmwareLosses,
                                 ConsoleText, MalformedLine>;

// One line, without its end (a trailing '\r' is ignored).
[[nodiscard]] ConsoleLine parse_console_line(std::string_view line);

// What the console said so far: the latest status, the latest line of each task, the end.
struct FirmwareReport {
  std::optional<FirmwareStatus> status;
  std::vector<FirmwareTask> tasks;                  // by index (at most 256); an index never reported has an empty name
  std::map<std::uint64_t, std::uint64_t> sections;  // the latest longest section in cycles, by ceiling
  std::optional<FirmwareEnd> end;
  std::optional<FirmwareLosses> losses;  // the latest
};

// Takes in a parsed line; text and malformed lines change nothing.
void take(FirmwareReport& report, const ConsoleLine& line);

}  // namespace duet::cli
