#pragma once
// SysTick as a free-running 24-bit counter of core clock cycles, for measuring short intervals.

#include <cstdint>

namespace duet::cortex_m::systick {

inline constexpr std::uint32_t counter_mask = 0x00FF'FFFF;

// Starts SysTick counting down from 2^24 - 1 at the core clock, without interrupts.
void start_free_running();

// The counter's current value; pass it to cycles_since() later.
std::uint32_t now();

// Core cycles since `earlier` (a value of now()), exact while the interval is shorter than 2^24 cycles.
inline std::uint32_t cycles_since(std::uint32_t earlier) { return (earlier - now()) & counter_mask; }

}  // namespace duet::cortex_m::systick
