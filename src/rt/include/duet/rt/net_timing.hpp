#pragma once
// Net execution times of nested interrupt handlers: a handler's time excludes the handlers that preempted it, so that
// the figures fit schedulability analysis (C_i), not response times.
//
// Without a stack of the tasks running: every task that finishes adds its net time to the busy total, so what
// preempted a task is exactly how much the busy total grew while it ran. A preempting task counts once in that growth
// however deeply the preemptions nest: its own net time and, added as each finished, the net times of whatever
// preempted it in turn. A task then notes two words when it starts and does three additions when it ends.

#include <cstdint>

namespace duet::rt {

class NetTiming {
 public:
  // What a task notes when it starts.
  struct Start {
    std::uint32_t cycles;
    std::uint32_t busy;  // the busy total's low word: only its growth matters
  };

  // `now_cycles` is the cycle count at which the task began. A task that finished between that count and this call
  // would be counted in the task's time: call at once, and read the count first (the other order would take such a
  // task out of a time that never held it).
  [[nodiscard]] Start begin(std::uint32_t now_cycles) const {
    return {now_cycles, static_cast<std::uint32_t>(busy_cycles_)};
  }

  // Returns the task's net cycles. Call with every task that uses this timing and may preempt the caller masked: the
  // busy total is read, changed and written. The cycle counter may wrap once per task.
  std::uint32_t end(Start start, std::uint32_t now_cycles) {
    const std::uint32_t preempted = static_cast<std::uint32_t>(busy_cycles_) - start.busy;
    const std::uint32_t net = now_cycles - start.cycles - preempted;
    busy_cycles_ += net;
    return net;
  }

  // Cycles spent in tasks, each counted once, since construction.
  [[nodiscard]] std::uint64_t busy_cycles() const { return busy_cycles_; }

 private:
  std::uint64_t busy_cycles_ = 0;
};

}  // namespace duet::rt
