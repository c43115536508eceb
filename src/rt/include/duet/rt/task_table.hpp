#pragma once
// What a model tells the executive about itself: its tasks, their rates, triggers and priorities, and its entry points.
// The executive knows nothing else of a model. Code generation emits one ModelDescription per model.

#include <cstdint>
#include <span>
#include <string_view>

namespace duet::rt {

enum class TaskKind : std::uint8_t {
  periodic,   // runs every `period_ticks` base ticks
  interrupt,  // runs when its interrupt source fires
};

// An NVIC priority: only `group` preempts; among pending tasks of one group, `sub` and then the lower interrupt
// number decide which runs first. 0 is the most urgent; both must fit the core's priority bits.
struct InterruptPriority {
  std::uint8_t group = 0;
  std::uint8_t sub = 0;
};

struct Task {
  std::string_view name;
  TaskKind kind = TaskKind::periodic;
  std::uint32_t period_ticks = 1;  // periodic: the period in base ticks (1 for the base rate)
  std::uint16_t interrupt = 0;     // interrupt: the board's interrupt number that triggers the task
  // The priority of the task's interrupt: for the base rate the timer's, for a slower rate in multitasking mode its
  // software interrupt's (less urgent than every faster rate), for an interrupt task its trigger's.
  InterruptPriority priority;
  void (*entry)() = nullptr;  // the rate's step, or the interrupt task's body
};

enum class TaskingMode : std::uint8_t {
  single,  // every due rate runs inside the base timer interrupt, fastest first
  multi,   // each slower rate runs in its own lower-priority software-triggered interrupt, rate-monotonic
};

enum class OverrunPolicy : std::uint8_t {
  count_and_skip,  // count the overrun and drop the late activation
  stop,            // count it and stop the model; terminate runs
};

struct ModelDescription {
  std::string_view name;
  std::uint32_t base_period_ns = 0;
  // The periodic rates first, fastest first, the base rate (period 1) at index 0; then the interrupt tasks.
  std::span<const Task> tasks;
  void (*initialize)() = nullptr;
  void (*terminate)() = nullptr;
  TaskingMode tasking_mode = TaskingMode::single;
  OverrunPolicy overrun_policy = OverrunPolicy::count_and_skip;
  std::uint64_t final_tick = 0;  // stop after this many base ticks; 0 runs until a stop request
  bool wait_for_start = false;   // wait for a start request (external mode) before the first tick
  // How many of the 4 NVIC priority bits are sub-priority (the rest are the group that preempts): 0 to 3.
  std::uint8_t sub_priority_bits = 0;
};

enum class TaskTableError : std::uint8_t {
  none,
  no_tasks,
  too_many_tasks,           // more than the executive was sized for
  no_base_rate,             // the first task is not periodic with period 1
  missing_entry,            // a task or the model lacks an entry point
  rates_not_fastest_first,  // periodic tasks out of order, or after an interrupt task
  zero_period,
  base_period_zero,
  priority_out_of_range,     // a group or sub-priority does not fit the bits the grouping gives it
  rates_not_rate_monotonic,  // multitasking: a slower rate is not less urgent than the rate before it
};

// Checks the rules above; usable in a static_assert on a constexpr table.
constexpr TaskTableError check(const ModelDescription& model) {
  if (model.tasks.empty()) return TaskTableError::no_tasks;
  if (model.base_period_ns == 0) return TaskTableError::base_period_zero;
  if (model.initialize == nullptr || model.terminate == nullptr) return TaskTableError::missing_entry;
  const Task& base = model.tasks.front();
  if (base.kind != TaskKind::periodic || base.period_ticks != 1) return TaskTableError::no_base_rate;
  constexpr unsigned nvic_priority_bits = 4;
  if (model.sub_priority_bits >= nvic_priority_bits) return TaskTableError::priority_out_of_range;
  const unsigned group_levels = 1U << (nvic_priority_bits - model.sub_priority_bits);
  const unsigned sub_levels = 1U << model.sub_priority_bits;
  bool seen_interrupt_task = false;
  for (std::size_t index = 0; index < model.tasks.size(); ++index) {
    const Task& task = model.tasks[index];
    if (task.entry == nullptr) return TaskTableError::missing_entry;
    if (task.priority.group >= group_levels || task.priority.sub >= sub_levels) {
      return TaskTableError::priority_out_of_range;
    }
    if (task.kind == TaskKind::interrupt) {
      seen_interrupt_task = true;
      continue;
    }
    if (task.period_ticks == 0) return TaskTableError::zero_period;
    if (index == 0) continue;
    const Task& faster = model.tasks[index - 1];
    if (seen_interrupt_task || task.period_ticks < faster.period_ticks) return TaskTableError::rates_not_fastest_first;
    if (model.tasking_mode == TaskingMode::multi && task.priority.group <= faster.priority.group) {
      return TaskTableError::rates_not_rate_monotonic;
    }
  }
  return TaskTableError::none;
}

// The number of periodic rates at the front of the table.
constexpr std::size_t rate_count(const ModelDescription& model) {
  std::size_t count = 0;
  while (count < model.tasks.size() && model.tasks[count].kind == TaskKind::periodic) ++count;
  return count;
}

}  // namespace duet::rt
