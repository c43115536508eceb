#pragma once
// The summary `duet pil` ends with, computed from what the run left behind: the plant's own recording and its
// session, what the firmware said on its console, the bridge's counters. Pure functions, so that each figure can be
// checked without QEMU.

#include <cstddef>
#include <optional>
#include <string>

#include "bridge_counters.hpp"
#include "duet/link/serve.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/plant_controls.hpp"
#include "firmware_console.hpp"
#include "machine_load.hpp"

namespace duet::cli {

// The robot's true tilt (the plant's observable "theta_deg") over a stretch of the run.
struct TiltStatistics {
  double from_s = 0;
  std::size_t samples = 0;
  double mean_deg = 0;
  double rms_deg = 0;
  double largest_abs_deg = 0;
};

// Over the rows at or after `from_s`; none when the recording has no theta_deg or no such row.
[[nodiscard]] std::optional<TiltStatistics> tilt_statistics(const model::Recording& recording, double from_s);

// A count of the board's 25 MHz timer as instructions: at -icount shift=N one instruction takes 2^N ns of the
// emulated clock, a timer tick 40 ns.
[[nodiscard]] double instructions_from_cycles(double cycles, int icount_shift);
// An estimate of the time those instructions take on the STM32MP15's 209 MHz Cortex-M4 at one instruction per
// cycle (QEMU counts instructions, not cycles: wait states and pipeline stalls are not in it).
[[nodiscard]] double estimated_us_at_209_mhz(double instructions);

struct PilRun {
  bool lock_step = false;
  int icount_shift = 2;
  double model_time_s = 0;                    // how far the run went
  double wall_s = 0;                          // the plant session's, or the whole run's when there was none
  std::optional<link::ServeSummary> session;  // none when the firmware never connected
  std::optional<TiltStatistics> tilt;         // the whole run
  std::optional<TiltStatistics> tilt_after_release;
  bool recording_truncated = false;
  FirmwareReport firmware;
  bool bridge = true;                  // false: --no-bridge
  std::optional<XcpTraffic> xcp;       // the bridge's counters, when it said them
  std::string daq;                     // what --signal recorded ("recorded N samples of ..."); empty: no --signal
  std::optional<MachineLoad> machine;  // what the rest of the machine did meanwhile
  // What the dashboards pushed and restarted, with the model times, and what the plant offers (for the names).
  std::vector<plant::AppliedDisturbance> disturbances;
  std::vector<plant::DisturbanceKind> offered;
};

// The share of ticks after the first second that may be later than the late threshold (1 ms) in a run that keeps
// real time; beyond it the summary says why it did not.
inline constexpr double late_ticks_allowed = 0.01;

// The summary, several lines, each ending with a newline.
[[nodiscard]] std::string format_summary(const PilRun& run);

}  // namespace duet::cli
