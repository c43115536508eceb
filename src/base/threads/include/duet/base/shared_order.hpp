#pragma once
// Acquire and release for data that threads share, possibly on several cores (the variant CMake chooses for the PC
// and Linux; single_core/ has the Cortex-M4's): the C++ orderings as they are.

#include <atomic>

namespace duet {

template <typename T>
[[nodiscard]] inline T load_acquire(const std::atomic<T>& shared) {
  return shared.load(std::memory_order_acquire);
}

template <typename T>
inline void store_release(std::atomic<T>& shared, T value) {
  shared.store(value, std::memory_order_release);
}

}  // namespace duet
