#pragma once
// Microseconds of the executive's clock, for DAQ timestamps (duet/cortex_m/microsecond_clock.hpp), from the board's
// 25 MHz cycle counter. It counts only once the executive's port has started the cycle counter
// (ExecutivePort::configure), and it stands still while the executive's time does (ExecutivePort::hold_time).

#include <cstdint>

#include "duet/cortex_m/microsecond_clock.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/executive_port.hpp"

namespace duet::mps2_an386 {

inline std::uint32_t elapsed_microseconds() {
  static cortex_m::MicrosecondClock<peripheral_clock_hz> clock;
  return clock.elapsed([] { return ExecutivePort{}.cycles(); });
}

}  // namespace duet::mps2_an386
