#pragma once
// Microseconds of the executive's clock, for DAQ timestamps in the unit duet's generated A2L files declare
// (TIMESTAMP_SUPPORTED 1 SIZE_DWORD UNIT_1US). The board's 25 MHz cycle counter wraps every 172 s; this count goes on
// across its wraps and wraps itself as a 32-bit count of microseconds should (every 72 minutes), provided something
// asks for it at least once per 172 s: DAQ does at every sample, an idle loop may too.
//
// Interrupt-safe (the XCP slave stamps from tasks of every priority and from its command handler), never waits. It
// counts only once the executive's port has started the cycle counter (ExecutivePort::configure), and it stands still
// while the executive's time does (ExecutivePort::hold_time).

#include <cstdint>

#include "duet/cortex_m/interrupts.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/executive_port.hpp"

namespace duet::mps2_an386 {

inline std::uint32_t elapsed_microseconds() {
  constexpr std::uint32_t cycles_per_microsecond = peripheral_clock_hz / 1'000'000U;
  static std::uint32_t last_cycles = 0;
  static std::uint32_t cycles_below_a_microsecond = 0;
  static std::uint32_t microseconds = 0;
  const cortex_m::InterruptMask masked;  // a read-modify-write of three counts that any priority may interrupt
  const std::uint32_t now = ExecutivePort{}.cycles();
  cycles_below_a_microsecond += now - last_cycles;
  last_cycles = now;
  microseconds += cycles_below_a_microsecond / cycles_per_microsecond;
  cycles_below_a_microsecond %= cycles_per_microsecond;
  return microseconds;
}

}  // namespace duet::mps2_an386
