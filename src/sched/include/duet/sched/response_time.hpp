#pragma once
// Exact response-time analysis of interrupt handlers under NVIC semantics (docs/SCHEDULING.md): fixed priorities with
// release jitter and blocking, arbitrary deadlines (every job of the level-i busy period), and priority grouping —
// a handler is dispatched by (group, sub-priority, IRQ number) but preempted only by a more urgent group, which is
// preemption-threshold scheduling. Start and finish times of each job follow Keskin, Bril and Lukkien (ETFA 2010).
// The analysis counts whole picoseconds (picoseconds.hpp), so it is exact and ends, also at utilization exactly 1.

#include <cstddef>
#include <limits>
#include <vector>

#include "duet/sched/task_set.hpp"
#include "duet/support/result.hpp"

namespace duet::sched {

inline constexpr double unbounded = std::numeric_limits<double>::infinity();

struct TaskResponse {
  double cost = 0;      // C with the core's entry and exit overheads
  double blocking = 0;  // B: a masked section, or a handler of the same group that has started
  double response = 0;  // worst-case R over the jobs of the busy period; `unbounded` if that never ends (or would
                        // last beyond 2^62 ps, about 53 days)
  double deadline = 0;
  std::size_t worst_job = 0;  // which job of the busy period (0 = the first) has R
  std::size_t jobs = 0;       // jobs examined
  [[nodiscard]] bool meets_deadline() const { return response <= deadline; }
  [[nodiscard]] double slack() const { return deadline - response; }
};

struct Analysis {
  std::vector<TaskResponse> tasks;  // in the task set's order
  [[nodiscard]] bool schedulable() const {
    for (const TaskResponse& task : tasks) {
      if (!task.meets_deadline()) return false;
    }
    return true;
  }
};

// Every task needs a priority (fixed or assigned) and a period; a task without them, or a time that is not a whole
// number of picoseconds (at most six decimals in microseconds), is an error naming it.
[[nodiscard]] Result<Analysis> analyse(const TaskSet& set);

// True if `a` is dispatched before `b` when both are pending: group, then sub-priority, then the lower IRQ number,
// then the earlier task in the set.
[[nodiscard]] bool dispatched_before(const TaskSet& set, std::size_t a, std::size_t b);

}  // namespace duet::sched
