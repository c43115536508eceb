#pragma once
// Rate transitions: how a value crosses from one task to another that runs at a different rate or from an interrupt.
//
// Between periodic rates the transfer is deterministic, as in Simulink's "ensure deterministic data transfer": the
// value changes hands only at the slower rate's release ticks, so what a task sees does not depend on how long the
// other one ran. Between an interrupt task and anything else there is no common time base; AsyncTransfer hands over the
// latest whole value without locks and without ever tearing it.

#include <array>
#include <atomic>
#include <cstdint>
#include <type_traits>

namespace duet::rt {

// Fast -> slow. The fast task writes every step; at the slow rate's release tick (Executive::is_release_tick) the
// value is latched, and the slow task reads that latched value during its whole period. Single-tasking and
// multitasking see the same values. Wait-free; the slow task must finish before its next release (else: overrun).
template <typename T>
class FastToSlow {
 public:
  // In the fast task, every step.
  void write(const T& value, bool slow_release_tick) {
    if (slow_release_tick) held_ = value;
  }
  // In the slow task.
  [[nodiscard]] const T& read() const { return held_; }
  // What the slow task reads until the first release. Before the tasks run.
  void reset(const T& initial) { held_ = initial; }

 private:
  T held_{};
};

// Slow -> fast, with a delay of one slow period (the only deterministic choice when the slow task may still be running
// while the fast one reads). The slow task writes once per activation; at each slow release tick the fast task takes
// the value of the activation that just completed and holds it for the slow period.
template <typename T>
class SlowToFast {
 public:
  // In the slow task.
  void write(const T& value) { produced_ = value; }
  // In the fast task, every step.
  [[nodiscard]] const T& read(bool slow_release_tick) {
    if (slow_release_tick) held_ = produced_;
    return held_;
  }
  // What the fast task reads until the slow task's first value arrives. Before the tasks run.
  void reset(const T& initial) {
    produced_ = initial;
    held_ = initial;
  }

 private:
  T produced_{};
  T held_{};
};

// Interrupt <-> periodic (either direction), one writer and one reader on one core: a triple buffer. The writer fills
// its own slot and publishes it with one atomic exchange; the reader takes the latest published slot with another.
// Neither waits for the other (wait-free), neither ever sees a half-written value, and the reader always gets the
// newest complete value. Values are copied; keep T small and trivially copyable.
template <typename T>
class AsyncTransfer {
  static_assert(std::is_trivially_copyable_v<T>, "AsyncTransfer copies values as they are");

 public:
  // In the writing task. Wait-free.
  void write(const T& value) {
    slots_[writer_slot_] = value;
    const auto published = static_cast<std::uint8_t>(writer_slot_ | fresh);
    writer_slot_ = static_cast<std::uint8_t>(exchange_.exchange(published, std::memory_order_acq_rel) & slot_mask);
  }

  // In the reading task: the newest value written, or the previous one again if nothing new came. Wait-free.
  [[nodiscard]] const T& read() {
    if ((exchange_.load(std::memory_order_relaxed) & fresh) != 0) {
      reader_slot_ = static_cast<std::uint8_t>(exchange_.exchange(reader_slot_, std::memory_order_acq_rel) & slot_mask);
    }
    return slots_[reader_slot_];
  }

  // What the reader gets until the first write. Before the tasks run (not interrupt-safe).
  void reset(const T& initial) {
    slots_.fill(initial);
    writer_slot_ = 0;
    reader_slot_ = 1;
    exchange_.store(2, std::memory_order_relaxed);
  }

 private:
  static constexpr std::uint8_t slot_mask = 0x3;
  static constexpr std::uint8_t fresh = 0x4;  // the exchanged slot holds a value the reader has not taken

  std::array<T, 3> slots_{};
  std::uint8_t writer_slot_ = 0;
  std::uint8_t reader_slot_ = 1;
  std::atomic<std::uint8_t> exchange_{2};
  static_assert(std::atomic<std::uint8_t>::is_always_lock_free);
};

}  // namespace duet::rt
