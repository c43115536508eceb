#pragma once
// The firmware's console (UART3): one line per fact, `key=value` words, so that `duet pil` and tests read them.
//
//   duet-pil model=balbot base_period_ns=1000000 tasks=11 duration_ms=10000       at start (0: until stopped)
//   duet-status time_s=1.000 ticks=1000 busy_ppm=123456 overruns=0              every second of model time
//   duet-task index=0 name=rate_1 activations=1000 overruns=0 min_cycles=... mean_cycles=... max_cycles=...
//   duet-channels xcp_received=... xcp_sent=... application_received=... application_sent=...
//   duet-lost xcp_responses=... daq_samples=... xcp_garbage_bytes=... telemetry_samples=... executive_reports=...
//             parameter_answers=...                                    what the channels dropped, each counted
//   duet-end reason=final_tick ticks=10001 overruns=0 link=ok                  once, when the model stopped
//
// A task line per task follows every status line, then the channels' line. Cycles count the board's 25 MHz timer
// (40 ns), which the plant link holds while it talks to the plant: net execution times, without preemption.
//
// A second's report is composed at once and written a line per base tick: QEMU writes the console a byte per system
// call, and the whole report (some 1,700 bytes) in one idle stretch took 3 to 12 ms of wall time inside one 1 ms
// tick, which a real-time run then had to catch up (docs/LINK.md, "Pacing"). A line costs a tick some 0.2 ms.

#include <cstdint>
#include <string_view>

#include "account_publisher.hpp"
#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/executive_report.hpp"
#include "duet/mps2_an386/plant_link.hpp"
#include "duet/rt/executive.hpp"
#include "robot_firmware.hpp"

namespace balbot::pil {

class StatusReport {
 public:
  explicit StatusReport(const duet::rt::ModelDescription& model) : model_(model) {}

  void started(std::uint64_t duration_ms) {
    line_.clear();
    line_.append("duet-pil model=").append(model_.name).append(" base_period_ns=").append(model_.base_period_ns);
    line_.append(" tasks=").append(model_.tasks.size()).append(" duration_ms=").append(duration_ms);
    emit();
    write_pending();
    ticks_per_report_ = 1'000'000'000U / model_.base_period_ns;
    next_report_ = ticks_per_report_;
  }

  // From the idle loop: the report of every second of model time that has passed, a line per tick.
  template <typename Executive>
  void between_ticks(const Executive& executive) {
    const std::uint64_t ticks = executive.ticks();
    if (ticks >= next_report_) {
      next_report_ += ticks_per_report_;
      write_pending();  // what is left of the last report, if its lines took more ticks than a second has
      status(executive);
    }
    if (ticks != last_line_tick_ && written_ < pending_.view().size()) {
      last_line_tick_ = ticks;
      write_line();
    }
  }

  template <typename Executive>
  void ended(const Executive& executive, const duet::mps2_an386::PlantLink& link) {
    status(executive);
    line_.clear();
    line_.append("duet-end reason=").append(reason(executive.stop_reason())).append(" ticks=");
    line_.append(executive.ticks()).append(" overruns=").append(duet::mps2_an386::total_overruns(executive, model_));
    line_.append(" link=").append(link.ok() ? std::string_view{"ok"} : link.error());
    emit();
    write_pending();
  }

 private:
  template <typename Executive>
  void status(const Executive& executive) {
    duet::mps2_an386::write_executive_report(executive, model_, [this](std::string_view line) { queue(line); });
    account_.publish(executive, duet::mps2_an386::core_clock_hz);
    const HostChannelCounters counters = host_channel_counters();
    line_.clear();
    line_.append("duet-channels xcp_received=").append(counters.xcp_bytes_received);
    line_.append(" xcp_sent=").append(counters.xcp_bytes_sent);
    line_.append(" application_received=").append(counters.application_bytes_received);
    line_.append(" application_sent=").append(counters.application_bytes_sent);
    emit();
    line_.clear();
    line_.append("duet-lost xcp_responses=").append(counters.lost.xcp_responses);
    line_.append(" daq_samples=").append(counters.lost.daq_overloads);
    line_.append(" xcp_garbage_bytes=").append(counters.lost.xcp_garbage_bytes);
    line_.append(" telemetry_samples=").append(counters.lost.telemetry);
    line_.append(" executive_reports=").append(counters.lost.executive_reports);
    line_.append(" parameter_answers=").append(counters.lost.answers);
    emit();
  }

  static std::string_view reason(duet::rt::StopReason reason) {
    switch (reason) {
      case duet::rt::StopReason::none: return "none";
      case duet::rt::StopReason::model: return "model";
      case duet::rt::StopReason::external: return "link";
      case duet::rt::StopReason::final_tick: return "final_tick";
      case duet::rt::StopReason::overrun: return "overrun";
    }
    return "unknown";
  }

  void emit() {
    line_.append('\n');
    queue(line_.view());
  }

  void queue(std::string_view line) {
    if (pending_.view().size() + line.size() > pending_capacity) write_pending();
    pending_.append(line);
  }

  // The next pending line.
  void write_line() {
    const std::string_view rest = pending_.view().substr(written_);
    std::size_t length = 0;  // up to its newline (a search of its own: string_view's wants the C library's memchr)
    while (length < rest.size() && rest[length++] != '\n') {
    }
    const std::string_view line = rest.substr(0, length);
    duet::cortex_m::console_write(line);
    written_ += line.size();
    if (written_ == pending_.view().size()) {
      pending_.clear();
      written_ = 0;
    }
  }

  void write_pending() {
    while (written_ < pending_.view().size()) write_line();
  }

  const duet::rt::ModelDescription& model_;
  static constexpr std::size_t pending_capacity = 4096;  // a report of 11 tasks is some 1,700 bytes

  duet::TextBuffer<240> line_;
  duet::TextBuffer<pending_capacity> pending_;  // lines not written yet, from written_ on
  std::size_t written_ = 0;
  std::uint64_t last_line_tick_ = 0;
  balbot::firmware::AccountPublisher account_{model_};
  std::uint64_t ticks_per_report_ = 1000;
  std::uint64_t next_report_ = 1000;
};

}  // namespace balbot::pil
