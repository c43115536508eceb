#pragma once
// The executive's account in memory, for XCP: what a master reads as the `executive.*` measurements of the A2L that
// duet gen writes (duet monitor's Status page, CANape, pyXCP). Words only, so that the layout has no padding and is
// the same on every target: ticks, busy ppm, overruns, the cycle counter's frequency, then per task (in the task
// table's order) activations, overruns, min, mean and max net execution time in cycles. The port refreshes it from
// the background loop (once a second is plenty); a master may read a refresh half done, which costs that second's
// consistency, never a fault.

#include <array>
#include <cstddef>
#include <cstdint>

namespace duet::rt {

struct TaskAccount {
  std::uint32_t activations;
  std::uint32_t overruns;
  std::uint32_t min_cycles;
  std::uint32_t mean_cycles;
  std::uint32_t max_cycles;
};

template <std::size_t task_count>
struct ExecutiveAccount {
  std::uint32_t ticks;  // the low 32 bits
  std::uint32_t busy_ppm;
  std::uint32_t overruns;
  std::uint32_t cycle_hz;
  std::array<TaskAccount, task_count> tasks;

  template <typename Executive>
  void update(const Executive& executive, std::uint32_t counter_hz) {
    std::uint32_t all_overruns = 0;
    for (std::size_t task = 0; task < task_count; ++task) {
      const auto& statistics = executive.statistics(task);
      tasks[task] = {statistics.activations, statistics.overruns,
                     statistics.activations == 0 ? 0U : statistics.min_cycles, statistics.mean_cycles(),
                     statistics.max_cycles};
      all_overruns += statistics.overruns;
    }
    ticks = static_cast<std::uint32_t>(executive.ticks());
    busy_ppm = executive.load().busy_ppm();
    overruns = all_overruns;
    cycle_hz = counter_hz;
  }
};

static_assert(sizeof(ExecutiveAccount<3>) == 16 + 3 * 20, "the A2L's layout: words only, no padding");

}  // namespace duet::rt
