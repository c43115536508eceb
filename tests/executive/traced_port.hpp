#pragma once
// The mps2-an386 executive port plus a trace: which task started and finished in which order, for tests that must
// see preemption happen.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/executive_port.hpp"

namespace duet::tests {

class TracedPort : public mps2_an386::ExecutivePort {
 public:
  void task_started(std::size_t task) { record(static_cast<std::uint8_t>(task << 1U)); }
  void task_finished(std::size_t task) { record(static_cast<std::uint8_t>((task << 1U) | 1U)); }
  // A critical section entered or left, for tests of priority ceilings.
  void section_entered() { record(section_entered_event); }
  void section_left() { record(section_left_event); }

  // Prints the first `count` events as "+task" (started), "-task" (finished), "[" and "]" (section entered, left).
  void print_trace(std::size_t count) const {
    TextBuffer<256> line;
    line.append("trace:");
    for (std::size_t event = 0; event < count && event < recorded_; ++event) {
      const std::uint8_t recorded = events_[event];
      line.append(' ');
      if (recorded >= section_entered_event) {
        line.append(recorded == section_entered_event ? '[' : ']');
      } else {
        line.append((recorded & 1U) != 0 ? '-' : '+').append(recorded >> 1U);
      }
    }
    cortex_m::console_write(line.append('\n').view());
  }

 private:
  // Every task records, so recording takes a section at their ceiling for the two statements it takes.
  void record(std::uint8_t event) {
    const CriticalSection masked{tasks_ceiling};
    if (recorded_ < events_.size()) events_[recorded_++] = event;
  }

  static constexpr std::uint8_t section_entered_event = 0xFE;  // above any task's events
  static constexpr std::uint8_t section_left_event = 0xFF;

  std::array<std::uint8_t, 128> events_{};
  std::size_t recorded_ = 0;
};

// "<name>: <activations> activations, <overruns> overruns"
template <typename Executive>
void print_task(const Executive& executive, std::size_t task, std::string_view name) {
  const auto& statistics = executive.statistics(task);
  TextBuffer<96> line;
  line.append(name).append(": ").append(statistics.activations).append(" activations, ");
  line.append(statistics.overruns).append(" overruns\n");
  cortex_m::console_write(line.view());
}

}  // namespace duet::tests
