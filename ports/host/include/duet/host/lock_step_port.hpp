#pragma once
// The executive's port for simulation and tests on the PC: time moves only when the caller advances it, so every run
// is the same. Each task has an interrupt line of its own in a SimulatedInterruptController (line = task index): the
// base timer, the slower rates' software interrupts, and the interrupt tasks, which the caller raises. Handlers run on
// the caller's thread in the NVIC's order; a task pended from inside a less urgent one preempts it there.
//
// Time is virtual: one cycle is one nanosecond, and a task takes no time unless it advances the clock itself.

#include <cstddef>
#include <cstdint>
#include <functional>

#include "duet/host/simulated_interrupt_controller.hpp"
#include "duet/host/task_lines.hpp"
#include "duet/rt/ceiling.hpp"
#include "duet/rt/task_table.hpp"

namespace duet::host {

class LockStepPort {
 public:
  struct CriticalSection {  // one thread runs every handler: nothing to mask
    explicit CriticalSection(rt::Ceiling /*ceiling*/) {}
  };

  explicit LockStepPort(const rt::ModelDescription& model);

  // Connects every task's line to `executive` (an rt::Executive on this port).
  template <typename Executive>
  void attach(Executive& executive);

  // Advances virtual time by `ticks` base periods, running the base tick and whatever it triggers at each.
  void advance(std::uint64_t ticks = 1);
  // An interrupt task's trigger fires now (its index in the task table).
  void raise(std::size_t task) { interrupts_.pend(task); }
  // Adds time spent inside a task, for models that simulate their execution time.
  void spend(std::uint64_t nanoseconds) { now_ns_ += nanoseconds; }
  [[nodiscard]] std::uint64_t now_ns() const { return now_ns_; }

  // ExecutivePort.
  [[nodiscard]] std::uint32_t cycles() const { return static_cast<std::uint32_t>(now_ns_); }
  void start_base_timer(std::uint32_t period_ns) { period_ns_ = period_ns; }
  void stop_base_timer() { period_ns_ = 0; }
  [[nodiscard]] bool base_tick_pending() const { return false; }  // a tick never arrives during a step
  void skip_base_tick() {}
  void trigger_rate(std::size_t rate) { interrupts_.pend(rate); }
  void idle() { advance(); }  // so that Executive::run() runs the model as fast as the PC can
  void task_finished(std::size_t task) const {
    if (on_task_finished) on_task_finished(task);
  }

  // Told of every task that finished, as a firmware's port tells its XCP slave (an event per task).
  std::function<void(std::size_t task)> on_task_finished;

 private:
  const rt::ModelDescription& model_;
  SimulatedInterruptController interrupts_;
  std::uint64_t now_ns_ = 0;
  std::uint32_t period_ns_ = 0;
};

template <typename Executive>
void LockStepPort::attach(Executive& executive) {
  connect_task_lines(interrupts_, model_, executive);
}

}  // namespace duet::host
