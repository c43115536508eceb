#pragma once
// Giving handlers NVIC priorities (docs/SCHEDULING.md).

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

// The set with the given priorities.
[[nodiscard]] TaskSet with_priorities(TaskSet set, const std::vector<NvicPriority>& priorities);

}  // namespace duet::sched
