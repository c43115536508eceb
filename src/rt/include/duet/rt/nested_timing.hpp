#pragma once
// Net execution times of nested interrupt handlers: a handler's time excludes the handlers that preempted it, so that
// the figures fit schedulability analysis (C_i), not response times.

#include <array>
#include <cstddef>
#include <cstdint>

namespace duet::rt {

class NestedTiming {
 public:
  // Thread mode plus one level per preemption priority: 16 on the STM32MP15, and QEMU is run with the same.
  static constexpr std::size_t max_depth = 17;

  // Call with interrupts masked, on entry to a task and on leaving it; handlers nest strictly (last in, first out).
  void begin(std::uint32_t now_cycles) {
    if (depth_ < max_depth) frames_[depth_] = {now_cycles, 0};
    ++depth_;
  }

  // Returns the task's net cycles. The cycle counter may wrap once per task.
  std::uint32_t end(std::uint32_t now_cycles) {
    --depth_;
    if (depth_ >= max_depth) return 0;  // deeper than any core nests: not measured
    const Frame& frame = frames_[depth_];
    const std::uint32_t gross = now_cycles - frame.start;
    if (depth_ == 0) {
      busy_cycles_ += gross;
    } else {
      frames_[depth_ - 1].preempted += gross;
    }
    return gross - frame.preempted;
  }

  // Cycles spent in outermost tasks (with everything that preempted them) since construction.
  [[nodiscard]] std::uint64_t busy_cycles() const { return busy_cycles_; }

 private:
  struct Frame {
    std::uint32_t start;
    std::uint32_t preempted;
  };
  std::array<Frame, max_depth> frames_{};
  std::size_t depth_ = 0;
  std::uint64_t busy_cycles_ = 0;
};

}  // namespace duet::rt
