#pragma once
// Acquire and release for data that interrupts share with the code they preempt, on a single M-profile core (the
// variant CMake chooses for Cortex-M4 builds; threads/ has the other). Every party is the same processor, which
// observes its own accesses in program order: only the compiler may reorder them, so a compiler fence is the whole
// barrier, and the `dmb` that a C++ acquire or release costs is left out.

#include <atomic>

namespace duet {

template <typename T>
[[nodiscard]] inline T load_acquire(const std::atomic<T>& shared) {
  const T value = shared.load(std::memory_order_relaxed);
  std::atomic_signal_fence(std::memory_order_acquire);
  return value;
}

template <typename T>
inline void store_release(std::atomic<T>& shared, T value) {
  std::atomic_signal_fence(std::memory_order_release);
  shared.store(value, std::memory_order_relaxed);
}

}  // namespace duet
