#pragma once
// Interrupt control of the Cortex-M core and its NVIC (ARMv7-M Architecture Reference Manual, B3.4).

#include <cstdint>

namespace duet::cortex_m {

// Priorities are 0 (most urgent) to 15. The STM32MP15 implements 4 priority bits and QEMU's mps2-an386 8, so duet
// only ever writes the top nibble: the same firmware orders its interrupts the same way on both.
inline constexpr unsigned priority_bits = 4;
inline constexpr unsigned priority_levels = 1U << priority_bits;

// Device interrupt numbers start at 0 for exception 16; the NVIC holds at most 496.
inline constexpr unsigned max_interrupt_count = 496;

// `priority` must be below priority_levels; a larger value is taken as the least urgent level rather than wrapping
// round to a more urgent one. All are interrupt-safe: each is a single store or read-modify-write of a byte the caller
// owns.
void enable_interrupt(unsigned interrupt_number);
void disable_interrupt(unsigned interrupt_number);
void set_interrupt_pending(unsigned interrupt_number);
void set_interrupt_priority(unsigned interrupt_number, unsigned priority);

inline void enable_interrupts() { asm volatile("cpsie i" ::: "memory"); }
inline void disable_interrupts() { asm volatile("cpsid i" ::: "memory"); }

// The exception being handled: 0 in thread mode, 1-15 for system exceptions, 16 + n for device interrupt n.
inline std::uint32_t active_exception() {
  std::uint32_t number;
  asm volatile("mrs %0, ipsr" : "=r"(number));
  return number & 0x1FFU;
}

}  // namespace duet::cortex_m
