#include "pil_summary.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string_view>

#include "pil_programs.hpp"

namespace duet::cli {
namespace {

constexpr std::string_view tilt_name = "theta_deg";

std::string fixed(double value, int digits) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(digits) << value;
  return text.str();
}

std::string describe(const TiltStatistics& tilt) {
  return "mean " + fixed(tilt.mean_deg, 2) + " deg, RMS " + fixed(tilt.rms_deg, 2) + " deg, largest |theta| " +
         fixed(tilt.largest_abs_deg, 2) + " deg";
}

std::string milliseconds(std::chrono::nanoseconds duration, int digits) {
  return fixed(std::chrono::duration<double, std::milli>(duration).count(), digits) + " ms";
}

std::string with_thousands(std::uint64_t count) {
  std::string digits = std::to_string(count);
  for (std::size_t at = digits.size(); at > 3; at -= 3) digits.insert(at - 3, ",");
  return digits;
}

void run_lines(const PilRun& run, std::ostream& out) {
  const double model_s = run.model_time_s;
  out << "  run       " << fixed(model_s, 3) << " s of model time in " << fixed(run.wall_s, 3) << " s of wall time";
  if (run.wall_s > 0) out << ": " << fixed(model_s / run.wall_s, 2) << " x real time";
  out << (run.lock_step ? " (lock-step)\n" : " (real time)\n");
}

// How well real time was kept, in words for someone who has not read the pacer: the figure after the first second
// (what the demonstration promises), how the late ticks came, whether the loop could keep real time at all, and when
// too many were late, why.
void pacing_lines(const PilRun& run, std::ostream& out) {
  if (run.lock_step || !run.session) return;
  const link::PacingReport& pacing = run.session->pacing;
  const link::Lateness& settled = pacing.after_first_second;
  const std::string late = "more than " + milliseconds(pacing.late_threshold, 0) + " late";
  constexpr std::string_view indent = "            ";
  out << "  pacing    ";
  if (settled.ticks == 0) {
    out << "the run ended within its first second (start-up), which is not judged\n";
  } else {
    out << "after the first second " << with_thousands(settled.late) << " of " << with_thousands(settled.ticks)
        << " ticks (" << fixed(100 * settled.late_fraction(), 2) << " %) were " << late
        << " (allowed: " << fixed(100 * late_ticks_allowed, 0) << " %)";
    if (settled.late > 0) out << ", the latest " << milliseconds(settled.worst, 1);
    out << '\n' << indent;
    if (const auto within = settled.within(0.99)) {
      out << "99 % within " << milliseconds(*within, 1);
    } else {
      out << "more than 1 % over " << milliseconds(link::Lateness::bin_bounds.back(), 0) << " late";
    }
    if (settled.late > 0) {
      out << "; late in " << with_thousands(settled.late_stretches) << " stretches, the longest "
          << with_thousands(settled.longest_stretch) << " ticks (each a fall behind, then catching up)";
    }
    out << '\n';
  }
  const link::Lateness& start = pacing.first_second;
  out << indent << "the first second (start-up): " << with_thousands(start.late) << " of "
      << with_thousands(start.ticks) << " ticks " << late;
  if (start.late > 0) out << ", the latest " << milliseconds(start.worst, 1);
  out << '\n';
  const std::optional<double> speed = pacing.loop_speed();
  if (speed) {
    out << indent << "without the waits QEMU, the firmware, the link and the plant went " << fixed(*speed, 2)
        << " x real time; the longest tick " << milliseconds(pacing.longest_busy, 1) << '\n';
  }
  const bool machine_busy = run.machine && run.machine->others_busy >= 0.5;
  const auto machine_line = [&] {
    return "other programs kept " + fixed(run.machine->others_busy, 1) + " of the machine's " +
           std::to_string(run.machine->processors) + " processors busy";
  };
  if (settled.ticks == 0 || settled.late_fraction() <= late_ticks_allowed) {
    if (run.machine) out << indent << machine_line() << '\n';
    return;
  }
  out << indent << "why: ";
  if (speed && *speed < 1) {
    out << "they went only " << fixed(*speed, 2)
        << " x real time: the emulator is slower than the robot's time, and each tick falls further behind\n";
  } else {
    // A run that went s x real time between its stalls catches up s - 1 seconds a second.
    out << "stalls: ticks that took long (the longest " << milliseconds(pacing.longest_busy, 1)
        << ") left the run behind";
    if (speed)
      out << ", and at " << fixed(*speed, 2) << " x real time it caught up " << fixed(*speed - 1, 2) << " s a second";
    out << '\n';
  }
  if (machine_busy) {
    out << indent << "     " << machine_line() << ": QEMU and the plant got theirs late\n";
  } else if (run.machine) {
    out << indent << "     " << machine_line() << '\n';
  }
}

void tilt_lines(const PilRun& run, std::ostream& out) {
  if (!run.tilt) return;
  out << "  tilt      whole run: " << describe(*run.tilt) << '\n';
  if (run.tilt_after_release) {
    out << "            from the release at " << fixed(run.tilt_after_release->from_s, 3)
        << " s: " << describe(*run.tilt_after_release) << '\n';
  }
  if (run.recording_truncated) out << "            (over the part of the run kept in memory)\n";
}

void task_table(const PilRun& run, std::ostream& out) {
  std::size_t name_width = 4;
  for (const FirmwareTask& task : run.firmware.tasks) name_width = std::max(name_width, task.name.size());
  const int width = static_cast<int>(name_width);
  out << "  tasks     instructions at -icount shift=" << run.icount_shift
      << "; us: an ESTIMATE for a 209 MHz core at one instruction per cycle\n";
  out << "            " << std::left << std::setw(width) << "task" << std::right << std::setw(12) << "activations"
      << std::setw(10) << "overruns" << std::setw(12) << "mean instr" << std::setw(11) << "max instr" << std::setw(15)
      << "max us (est.)" << '\n';
  for (const FirmwareTask& task : run.firmware.tasks) {
    if (task.name.empty()) continue;  // an index the firmware never reported
    const double mean = instructions_from_cycles(static_cast<double>(task.mean_cycles), run.icount_shift);
    const double max = instructions_from_cycles(static_cast<double>(task.max_cycles), run.icount_shift);
    out << "            " << std::left << std::setw(width) << task.name << std::right << std::setw(12)
        << task.activations << std::setw(10) << task.overruns << std::setw(12) << fixed(mean, 0) << std::setw(11)
        << fixed(max, 0) << std::setw(15) << fixed(estimated_us_at_209_mhz(max), 2) << '\n';
  }
  // Blocking for `duet sched` (duet model tasks --measured takes it from the console).
  for (const auto& [ceiling, cycles] : run.firmware.sections) {
    const double longest = instructions_from_cycles(static_cast<double>(cycles), run.icount_shift);
    out << "            longest section at ceiling " << ceiling << ": " << fixed(longest, 0) << " instr, "
        << fixed(estimated_us_at_209_mhz(longest), 2) << " us (est.)\n";
  }
}

void firmware_lines(const PilRun& run, std::ostream& out) {
  const FirmwareReport& firmware = run.firmware;
  if (!firmware.status && !firmware.end) {
    out << "  firmware  said nothing on its console (no duet-status line)\n";
    return;
  }
  const std::uint64_t ticks = firmware.end ? firmware.end->ticks : firmware.status->ticks;
  const std::uint64_t overruns = firmware.end ? firmware.end->overruns : firmware.status->overruns;
  out << "  firmware  " << ticks << " ticks, " << overruns << " overruns";
  if (firmware.status) out << ", core load " << fixed(static_cast<double>(firmware.status->busy_ppm) / 1e4, 2) << " %";
  if (firmware.end) out << "; ended: " << firmware.end->reason;
  out << '\n';
  if (!firmware.tasks.empty()) task_table(run, out);
  if (firmware.losses) {
    std::string lost;
    for (const auto& [name, count] : firmware.losses->counts) {
      if (count != 0) lost += (lost.empty() ? "" : ", ") + std::to_string(count) + " " + name;
    }
    out << "  lost      " << (lost.empty() ? "nothing" : lost) << " (the firmware's channels)\n";
  }
}

void xcp_lines(const PilRun& run, std::ostream& out) {
  if (!run.bridge) {
    out << "  xcp       no bridge (--no-bridge)\n";
  } else if (!run.xcp) {
    out << "  xcp       the bridge did not report its counters\n";
  } else {
    const XcpTraffic& xcp = *run.xcp;
    out << "  xcp       " << xcp.frames_to_slave << " frames to the slave (" << xcp.bytes_to_slave << " bytes), "
        << xcp.frames_to_master << " to the master (" << xcp.bytes_to_master << " bytes), " << xcp.daq_frames_dropped
        << " DAQ frames dropped, " << xcp.masters_served << " masters served\n";
  }
  if (!run.daq.empty()) out << "  daq       " << run.daq << '\n';
}

// "push force_n=5 duration_s=0.05 at 12.345 s": numbers that read back as the same doubles.
std::string describe_applied(const plant::AppliedDisturbance& applied,
                             const std::vector<plant::DisturbanceKind>& offered) {
  std::string text = applied.disturbance.name;
  const auto kind = std::find_if(offered.begin(), offered.end(), [&](const plant::DisturbanceKind& candidate) {
    return candidate.name == applied.disturbance.name;
  });
  for (std::size_t k = 0; k < applied.disturbance.arguments.size(); ++k) {
    const std::string name =
        kind != offered.end() && k < kind->arguments.size() ? kind->arguments[k].name : "#" + std::to_string(k);
    text += " " + name + "=" + shortest(applied.disturbance.arguments[k]);
  }
  return text + " at " + shortest(applied.time_s) + " s";
}

// Each with its model time, exactly: to repeat the run, a scenario with these pushes at these times.
void disturbance_lines(const PilRun& run, std::ostream& out) {
  if (run.disturbances.empty()) return;
  out << "  disturbed " << run.disturbances.size() << (run.disturbances.size() == 1 ? " time" : " times")
      << " through the plant's control endpoint:\n";
  for (const plant::AppliedDisturbance& applied : run.disturbances) {
    out << "            " << describe_applied(applied, run.offered) << '\n';
  }
}

}  // namespace

std::optional<TiltStatistics> tilt_statistics(const model::Recording& recording, double from_s) {
  const auto column = std::find(recording.names.begin(), recording.names.end(), tilt_name);
  if (column == recording.names.end()) return std::nullopt;
  const std::vector<double>& theta = recording.columns[static_cast<std::size_t>(column - recording.names.begin())];
  TiltStatistics tilt{.from_s = from_s};
  double sum = 0;
  double squares = 0;
  for (std::size_t row = 0; row < recording.time_s.size() && row < theta.size(); ++row) {
    if (recording.time_s[row] < from_s) continue;
    ++tilt.samples;
    sum += theta[row];
    squares += theta[row] * theta[row];
    tilt.largest_abs_deg = std::max(tilt.largest_abs_deg, std::abs(theta[row]));
  }
  if (tilt.samples == 0) return std::nullopt;
  const auto count = static_cast<double>(tilt.samples);
  tilt.mean_deg = sum / count;
  tilt.rms_deg = std::sqrt(squares / count);
  return tilt;
}

double instructions_from_cycles(double cycles, int icount_shift) {
  constexpr double timer_tick_ns = 40;  // 25 MHz
  return cycles * timer_tick_ns / std::ldexp(1.0, icount_shift);
}

double estimated_us_at_209_mhz(double instructions) { return instructions / 209; }

std::string format_summary(const PilRun& run) {
  std::ostringstream out;
  out << "summary\n";
  run_lines(run, out);
  pacing_lines(run, out);
  tilt_lines(run, out);
  if (run.session) {
    out << "  link      " << run.session->ticks << " ticks, " << run.session->interrupts << " interrupts, "
        << run.session->writes << " writes, " << run.session->reads << " reads\n";
  } else {
    out << "  link      the firmware never connected\n";
  }
  disturbance_lines(run, out);
  firmware_lines(run, out);
  xcp_lines(run, out);
  return out.str();
}

}  // namespace duet::cli
