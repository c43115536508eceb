#pragma once
// Priority ceilings (the Stack Resource Policy, as RTIC uses it): data that several tasks share is guarded by masking,
// for the length of a short section, the interrupts of the most urgent task that uses it and of everything less
// urgent. A task that uses the data then cannot run while another is inside the section, and every more urgent
// task, which does not use it, is never delayed. A task already at the ceiling needs no section at all: nothing that
// uses the data can preempt it. The ceilings come from the task table, at compile time for a constexpr table.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "duet/rt/task_table.hpp"

namespace duet::rt {

// A ceiling: the NVIC priority value (4 bits, 0 most urgent) of the most urgent group among a resource's users, with
// the sub-priority bits zero. Masking that value masks the whole group, since the NVIC masks by group.
struct Ceiling {
  std::uint8_t priority = 0;
  bool operator==(const Ceiling&) const = default;
};

// Task `index`'s group as an NVIC priority value with the sub-priority bits zero.
constexpr std::uint8_t group_priority(const ModelDescription& model, std::size_t index) {
  return static_cast<std::uint8_t>(model.tasks[index].priority.group << model.sub_priority_bits);
}

// The ceiling of a resource that the tasks `users` (indices into the task table; at least one) share.
constexpr Ceiling ceiling(const ModelDescription& model, std::span<const std::size_t> users) {
  std::uint8_t most_urgent = UINT8_MAX;
  for (const std::size_t user : users) {
    const std::uint8_t priority = group_priority(model, user);
    if (priority < most_urgent) most_urgent = priority;
  }
  return {most_urgent};
}

// Not constexpr and never defined: calling it ends a constant evaluation with a compile error that names it.
std::size_t the_task_table_has_no_task_of_that_name();

// The index of the task named `name` in the model's table, for constexpr use (a ceiling from the generated table).
constexpr std::size_t task_index(const ModelDescription& model, std::string_view name) {
  for (std::size_t index = 0; index < model.tasks.size(); ++index) {
    if (model.tasks[index].name == name) return index;
  }
  return the_task_table_has_no_task_of_that_name();
}

// The ceiling of what every task shares: the executive's timing of nested tasks, and the port's time and task hooks.
constexpr Ceiling tasks_ceiling(const ModelDescription& model) {
  std::uint8_t most_urgent = UINT8_MAX;
  for (std::size_t index = 0; index < model.tasks.size(); ++index) {
    const std::uint8_t priority = group_priority(model, index);
    if (priority < most_urgent) most_urgent = priority;
  }
  return {most_urgent};
}

// The longest section measured at each ceiling, in cycles: what a section at that ceiling can delay a task at or
// below it by (blocking, for `duet sched`: docs/SCHEDULING.md). Written inside the sections themselves: a section of
// one ceiling excludes every other writer of its entry, and a more urgent one writes another entry.
class SectionTiming {
 public:
  static constexpr std::size_t levels = 16;  // the STM32MP15's 4 priority bits

  void record(Ceiling ceiling, std::uint32_t cycles) {
    std::uint32_t& longest = longest_[ceiling.priority % levels];
    if (cycles > longest) longest = cycles;
  }
  [[nodiscard]] std::uint32_t longest(Ceiling ceiling) const { return longest_[ceiling.priority % levels]; }

 private:
  std::array<std::uint32_t, levels> longest_{};
};

}  // namespace duet::rt
