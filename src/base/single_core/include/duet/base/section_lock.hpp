#pragma once
// The lock around a short section that a single M-profile core's interrupts share (the variant CMake chooses for
// Cortex-M4 builds; threads/ has the other): the interrupt mask, set and restored inline. It nests and works in
// handlers. Inline because it guards the XCP transmit queue, which every DAQ event takes: a call through a pointer
// cost a tenth of an event.

#include <cstdint>

namespace duet {

struct SectionLock {
  // Masks every interrupt; returns the mask as it was.
  [[nodiscard]] std::uint32_t lock() const {
    std::uint32_t saved_primask = 0;
    asm volatile("mrs %0, primask\n cpsid i" : "=r"(saved_primask)::"memory");
    return saved_primask;
  }
  void unlock(std::uint32_t saved_primask) const { asm volatile("msr primask, %0" ::"r"(saved_primask) : "memory"); }
};

}  // namespace duet
