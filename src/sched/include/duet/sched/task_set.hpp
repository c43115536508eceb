#pragma once
// An interrupt-driven task set on one core, as the schedulability analysis sees it (docs/SCHEDULING.md). Times are in
// microseconds. Each task is an interrupt handler: released by its source at most once per period (or minimum
// inter-arrival time), with a release jitter, running for at most its worst-case execution time.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace duet::sched {

// An NVIC priority split by the priority grouping: lower numbers are more urgent. Only the group priority preempts.
struct NvicPriority {
  int group = 0;
  int sub = 0;
  bool operator==(const NvicPriority&) const = default;
};

struct Task {
  std::string name;
  double wcet = 0;                       // C
  double period = 0;                     // T, or the minimum inter-arrival time
  double deadline = 0;                   // D, relative to the release
  double jitter = 0;                     // J, release jitter (also the hardware's interrupt latency)
  std::string source;                    // the interrupt source; tasks of one source share its handler's priority
  int irq = 0;                           // the IRQ number: the NVIC's last tie-breaker among pending handlers
  std::optional<NvicPriority> priority;  // fixed by the user, or assigned
};

// The longest critical section measured at a priority ceiling (BASEPRI at the most urgent group of the tasks that
// share what it guards): it can delay every task whose group is that urgent or less (docs/SCHEDULING.md).
struct CeilingSection {
  int ceiling = 0;     // the group priority
  double longest = 0;  // microseconds
};

struct Core {
  int priority_bits = 4;      // implemented NVIC priority bits (16 levels on the STM32MP15)
  int sub_priority_bits = 0;  // of those, how many are sub-priority (the priority grouping)
  double entry_overhead = 0;  // exception entry, added to each handler's C
  double exit_overhead = 0;   // exception exit, likewise
  double masked_section = 0;  // the longest time every interrupt is masked (PRIMASK): blocking for every handler
  std::vector<CeilingSection> sections;  // sections at a ceiling: blocking for the handlers at or below it
};

struct TaskSet {
  Core core;
  std::vector<Task> tasks;
};

}  // namespace duet::sched
