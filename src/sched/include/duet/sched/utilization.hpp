#pragma once
// Utilization tests: quick and only sufficient (docs/SCHEDULING.md); the response-time analysis is exact.

#include <cstddef>

#include "duet/sched/task_set.hpp"

namespace duet::sched {

struct Utilization {
  double by_period = 0;           // sum C/T
  double by_deadline = 0;         // sum C/D (the thesis' deadline-monotonic check)
  double liu_layland_bound = 0;   // n (2^(1/n) - 1)
  double hyperbolic_product = 0;  // prod (C/T + 1); the hyperbolic bound holds while it is <= 2
  [[nodiscard]] bool passes_liu_layland() const { return by_period <= liu_layland_bound; }
  [[nodiscard]] bool passes_hyperbolic() const { return hyperbolic_product <= 2.0; }
  [[nodiscard]] bool passes_deadline_check() const { return by_deadline <= liu_layland_bound; }
};

[[nodiscard]] double liu_layland_bound(std::size_t tasks);
// With each C plus the core's entry and exit overheads, as the response-time analysis counts it.
[[nodiscard]] Utilization utilization(const TaskSet& set);

}  // namespace duet::sched
