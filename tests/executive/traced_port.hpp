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

  // Prints the first `count` events as "+task" (started) and "-task" (finished).
  void print_trace(std::size_t count) const {
    TextBuffer<256> line;
    line.append("trace:");
    for (std::size_t event = 0; event < count && event < recorded_; ++event) {
      line.append(' ').append((events_[event] & 1U) != 0 ? '-' : '+').append(events_[event] >> 1U);
    }
    cortex_m::console_write(line.append('\n').view());
  }

 private:
  // Handlers nest, so recording masks interrupts for the two statements it takes.
  void record(std::uint8_t event) {
    const cortex_m::InterruptMask masked;
    if (recorded_ < events_.size()) events_[recorded_++] = event;
  }

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
