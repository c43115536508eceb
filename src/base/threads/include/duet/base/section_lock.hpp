#pragma once
// The lock around a short section that threads share (the variant CMake chooses for the PC and Linux;
// single_core/ has the Cortex-M4's): the program's own pair of functions, typically around a mutex. lock() returns
// what unlock() needs. Without functions there is no lock, for a section that one thread alone enters.

#include <cstdint>

namespace duet {

struct SectionLock {
  std::uint32_t (*lock_function)() = nullptr;
  void (*unlock_function)(std::uint32_t saved) = nullptr;

  [[nodiscard]] std::uint32_t lock() const { return lock_function != nullptr ? lock_function() : 0; }
  void unlock(std::uint32_t saved) const {
    if (unlock_function != nullptr) unlock_function(saved);
  }
};

}  // namespace duet
