#pragma once
// A model's tasks on the NVIC: which line runs each task, and at what priority, from the model's task table (4
// priority bits, split into group and sub-priority as the model says). The base rate runs on the board's base timer,
// each slower rate (multitasking) on a line the board pends from software, each interrupt task on its trigger's line.

#include <cstddef>
#include <span>

#include "duet/cortex_m/interrupts.hpp"
#include "duet/rt/task_table.hpp"

namespace duet::cortex_m {

struct TaskLines {
  unsigned base_timer;
  std::span<const unsigned> rates;  // rates[r] runs slower rate r; rates[0] is not used (the base timer runs rate 0)
};

struct TaskInterrupt {
  unsigned line;
  unsigned priority;  // the NVIC's value, 0 most urgent
};

// Task `index` of `model`: a rate beyond `lines.rates` has no line (a model the board cannot run; see
// configure_task_interrupts).
constexpr TaskInterrupt task_interrupt(const rt::ModelDescription& model, std::size_t index, const TaskLines& lines) {
  const rt::Task& task = model.tasks[index];
  const bool slower_rate = index != 0 && index < rt::rate_count(model);
  const unsigned line = index == 0 ? lines.base_timer : slower_rate ? lines.rates[index] : task.interrupt;
  return {line, grouped_priority(task.priority.group, task.priority.sub, model.sub_priority_bits)};
}

// Sets the priority grouping, each task's priority, and enables each task's line. False, with nothing touched, if
// the model has more rates than the board has lines for. Call before enabling interrupts.
inline bool configure_task_interrupts(const rt::ModelDescription& model, const TaskLines& lines) {
  if (rt::rate_count(model) > lines.rates.size()) return false;
  set_priority_grouping(model.sub_priority_bits);
  for (std::size_t index = 0; index < model.tasks.size(); ++index) {
    const TaskInterrupt interrupt = task_interrupt(model, index, lines);
    set_interrupt_priority(interrupt.line, interrupt.priority);
    enable_interrupt(interrupt.line);
  }
  return true;
}

}  // namespace duet::cortex_m
