#pragma once
// The DWT cycle counter of the Cortex-M3/M4/M7 (ARMv7-M Architecture Reference Manual, C1.8): 32 bits of core clock
// cycles, the finest clock for execution times on hardware. QEMU does not emulate it (it reads as zero there), so
// the mps2-an386 port counts with a timer instead; the STM32MP15 port uses this.

#include <cstdint>

#include "duet/cortex_m/registers.hpp"

namespace duet::cortex_m::cycle_counter {

// Enables trace (DEMCR.TRCENA), clears the counter and starts it (DWT_CTRL.CYCCNTENA).
inline void start() {
  constexpr std::uintptr_t debug_exception_and_monitor_control = 0xE000EDFC;
  constexpr std::uintptr_t dwt_control = 0xE0001000;
  constexpr std::uintptr_t dwt_cycle_count = 0xE0001004;
  register32(debug_exception_and_monitor_control) = register32(debug_exception_and_monitor_control) | (1U << 24);
  register32(dwt_cycle_count) = 0;
  register32(dwt_control) = register32(dwt_control) | 1U;
}

// Core clock cycles since start(); wraps after 2^32 cycles (20.5 s at 209 MHz).
[[nodiscard]] inline std::uint32_t now() { return register32(0xE0001004); }

}  // namespace duet::cortex_m::cycle_counter
