#pragma once
// What the executive measures for each task, kept in plain memory so that XCP can read it while the model runs.

#include <cstdint>

namespace duet::rt {

struct TaskStatistics {
  std::uint32_t activations = 0;          // completed runs
  std::uint32_t overruns = 0;             // releases that found the previous one unfinished
  std::uint32_t min_cycles = UINT32_MAX;  // net execution time: without the tasks that preempted it
  std::uint32_t max_cycles = 0;
  std::uint64_t total_cycles = 0;

  constexpr void record(std::uint32_t cycles) {
    ++activations;
    total_cycles += cycles;
    if (cycles < min_cycles) min_cycles = cycles;
    if (cycles > max_cycles) max_cycles = cycles;
  }

  [[nodiscard]] constexpr std::uint32_t mean_cycles() const {
    return activations == 0 ? 0 : static_cast<std::uint32_t>(total_cycles / activations);
  }
};

// Cycles spent in tasks against cycles elapsed since the executive began; the rest is idle time.
struct CoreLoad {
  std::uint64_t busy_cycles = 0;
  std::uint64_t elapsed_cycles = 0;

  // The busy share in parts per million (1'000'000 = fully loaded).
  [[nodiscard]] constexpr std::uint32_t busy_ppm() const {
    if (elapsed_cycles == 0) return 0;
    const std::uint64_t busy = busy_cycles < elapsed_cycles ? busy_cycles : elapsed_cycles;
    return static_cast<std::uint32_t>(busy * 1'000'000U / elapsed_cycles);
  }
};

}  // namespace duet::rt
