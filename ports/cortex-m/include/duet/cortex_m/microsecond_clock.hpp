#pragma once
// Microseconds from a free-running 32-bit cycle counter, for DAQ timestamps in the unit duet's generated A2L files
// declare (TIMESTAMP_SUPPORTED 1 SIZE_DWORD UNIT_1US). The count goes on across the cycle counter's wraps (every
// 2^32 / CyclesPerSecond seconds: 172 s at 25 MHz, 20.5 s at 209 MHz) and wraps itself as a 32-bit count of
// microseconds should (every 72 minutes), provided something asks at least once per cycle-counter wrap: DAQ does at
// every sample, an idle loop may too. Interrupt-safe (the XCP slave stamps from tasks of every priority and from its
// command handler), never waits.

#include <cstdint>

#include "duet/cortex_m/interrupts.hpp"

namespace duet::cortex_m {

template <std::uint32_t CyclesPerSecond>
class MicrosecondClock {
 public:
  static_assert(CyclesPerSecond % 1'000'000U == 0, "a whole number of cycles per microsecond");

  // `read_cycles()` reads the cycle counter; it is read here, masked, so that no interrupt updates the counts
  // between the reading and its use.
  template <typename ReadCycles>
  std::uint32_t elapsed(ReadCycles read_cycles) {
    const InterruptMask masked;  // a read-modify-write of three counts that any priority may interrupt
    const std::uint32_t cycles_now = read_cycles();
    below_a_microsecond_ += cycles_now - last_cycles_;
    last_cycles_ = cycles_now;
    microseconds_ += below_a_microsecond_ / cycles_per_microsecond;
    below_a_microsecond_ %= cycles_per_microsecond;
    return microseconds_;
  }

 private:
  static constexpr std::uint32_t cycles_per_microsecond = CyclesPerSecond / 1'000'000U;
  std::uint32_t last_cycles_ = 0;
  std::uint32_t below_a_microsecond_ = 0;
  std::uint32_t microseconds_ = 0;
};

}  // namespace duet::cortex_m
