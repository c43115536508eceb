#pragma once
// Giving handlers NVIC priorities (docs/SCHEDULING.md).

#include <cstddef>
#include <optional>
#include <vector>

#include "duet/sched/task_set.hpp"

namespace duet::sched {

// The thesis' deadline-monotonic rules (its table 4.10): by deadline, ties by C/D descending; tasks of one interrupt
// source share a level (they are one handler), and so do tasks equal in both D and C/D. Levels are group priorities
// numbered from `first_level` in that order (the thesis starts at 1); sub-priorities 0.
[[nodiscard]] std::vector<NvicPriority> deadline_monotonic(const TaskSet& set, int first_level = 1);

// Audsley's optimal priority assignment: from the least urgent level up, a task that meets its deadline there with
// all unassigned tasks more urgent. Tasks of one source share a level. Levels are group priorities numbered from
// `first_level`; none if no fixed-priority order meets every deadline.
[[nodiscard]] std::optional<std::vector<NvicPriority>> optimal_priorities(const TaskSet& set, int first_level = 0);

// Fits the set's group priorities onto `levels` NVIC group levels numbered from `first_level`, keeping their order:
// when there are more distinct groups than levels, neighbouring groups are merged (handlers then share a level and no
// longer preempt each other), least urgent first, as long as every deadline is still met. None if that cannot be done.
struct LevelFit {
  std::vector<NvicPriority> priorities;
  std::vector<std::vector<std::size_t>> shared;  // the tasks that share a level because of the fit
};
[[nodiscard]] std::optional<LevelFit> fit_to_levels(const TaskSet& set, int levels, int first_level = 0);

// The set with the given priorities.
[[nodiscard]] TaskSet with_priorities(TaskSet set, const std::vector<NvicPriority>& priorities);

}  // namespace duet::sched
