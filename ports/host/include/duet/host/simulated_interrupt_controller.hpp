#pragma once
// An NVIC for the PC: interrupt lines with a group and a sub-priority, pended by software, run by one thread at a
// time in the NVIC's order. Pending a line more urgent than the running handler's group runs it at once, nested, as
// preemption would; anything else waits until the running handler returns. Among waiting lines the most urgent group
// runs first, then the lower sub-priority, then the lower line number.
//
// Not thread-safe by itself: a port that pends from several threads serialises the calls.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace duet::host {

class SimulatedInterruptController {
 public:
  struct Priority {
    std::uint8_t group = 0;
    std::uint8_t sub = 0;
  };

  explicit SimulatedInterruptController(std::size_t line_count);

  // Installs the handler of `line` and its priority; a line without one stays quiet when pended.
  void connect(std::size_t line, Priority priority, std::function<void()> handler);

  // Pends `line`; runs it before returning if it may preempt what runs now (or nothing runs).
  void pend(std::size_t line);

  [[nodiscard]] bool pending(std::size_t line) const { return lines_.at(line).pending; }
  void clear_pending(std::size_t line) { lines_.at(line).pending = false; }

 private:
  static constexpr unsigned thread_mode = 0x100;  // less urgent than any group

  struct Line {
    Priority priority;
    std::function<void()> handler;
    bool pending = false;
  };

  // Runs pending lines that may preempt the running group, most urgent first, until none is left.
  void dispatch();

  std::vector<Line> lines_;
  unsigned running_group_ = thread_mode;
};

}  // namespace duet::host
