#include "duet/sched/utilization.hpp"

#include <cmath>

namespace duet::sched {

double liu_layland_bound(std::size_t tasks) {
  if (tasks == 0) return 1.0;
  const double n = static_cast<double>(tasks);
  return n * (std::pow(2.0, 1.0 / n) - 1.0);
}

Utilization utilization(const TaskSet& set) {
  Utilization result;
  result.hyperbolic_product = 1.0;
  const double overheads = set.core.entry_overhead + set.core.exit_overhead;
  for (const Task& task : set.tasks) {
    const double cost = task.wcet + overheads;
    result.by_period += cost / task.period;
    result.by_deadline += cost / task.deadline;
    result.hyperbolic_product *= cost / task.period + 1.0;
  }
  result.liu_layland_bound = liu_layland_bound(set.tasks.size());
  return result;
}

}  // namespace duet::sched
