#pragma once
// The Arm CMSDK APB timer (QEMU's cmsdk-apb-timer): a 32-bit down-counter that reloads and can interrupt at zero.

#include <cstdint>

#include "duet/cortex_m/registers.hpp"

namespace duet::mps2_an386 {

class CmsdkTimer {
 public:
  explicit constexpr CmsdkTimer(std::uintptr_t base) : base_(base) {}

  // Interrupts every `period_cycles` peripheral clock cycles (at least 2), starting one period from now.
  void start_periodic_interrupt(std::uint32_t period_cycles) const;
  // Counts down from 2^32 - 1 without interrupts, wrapping: a free-running clock of the peripheral clock.
  void start_free_running() const;
  void stop() const;

  // The counter: counts down by one per peripheral clock cycle.
  [[nodiscard]] std::uint32_t value() const { return cortex_m::register32(base_ + value_offset); }

  // Acknowledges the interrupt; the handler must call it, or the interrupt is taken again at once. Interrupt-safe.
  void clear_interrupt() const { cortex_m::register32(base_ + interrupt_clear_offset) = 1; }

 private:
  // Inline here because the executive reads and acknowledges them on every tick.
  static constexpr std::uintptr_t value_offset = 0x4;
  static constexpr std::uintptr_t interrupt_clear_offset = 0xC;
  std::uintptr_t base_;
};

}  // namespace duet::mps2_an386
