#pragma once
// A discrete-event simulation of interrupt handlers under NVIC semantics, to check the analysis against: a pending
// handler is dispatched by (group, sub-priority, IRQ number) and preempts the running one only if its group is more
// urgent. Every release is a job of its own (queued per task), as the analysis assumes. Each job runs for the task's
// C plus the core's entry and exit overheads.

#include <cstddef>
#include <utility>
#include <vector>

#include "duet/sched/task_set.hpp"

namespace duet::sched {

struct Release {
  std::size_t task = 0;
  double arrival = 0;  // when the event happened
  double release = 0;  // when the interrupt became pending: arrival + a delay of at most the task's jitter
};

struct SimulatedJob {
  std::size_t task = 0;
  double arrival = 0;
  double start = 0;
  double finish = 0;
  std::vector<std::pair<double, double>> runs;  // when it ran: [from, to) pieces between preemptions
  [[nodiscard]] double response() const { return finish - arrival; }
};

// Runs the releases (any order) until every job has finished. Every task needs a priority.
[[nodiscard]] std::vector<SimulatedJob> simulate(const TaskSet& set, std::vector<Release> releases);

// The classic critical instant: each task's first event at `offsets[i]` (0 if not given) - J, held back the whole
// jitter; later events every T, passed on at once; events before `until`.
[[nodiscard]] std::vector<Release> critical_instant(const TaskSet& set, double until,
                                                    const std::vector<double>& offsets = {});

// The largest response of each task's jobs (0 for a task without jobs).
[[nodiscard]] std::vector<double> largest_responses(const TaskSet& set, const std::vector<SimulatedJob>& jobs);

}  // namespace duet::sched
