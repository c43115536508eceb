#pragma once
// Memory-mapped registers of the Cortex-M core and of peripherals.

#include <cstdint>

namespace duet::cortex_m {

// The 32-bit register at `address`. Every access is a real bus access (volatile), in program order.
inline volatile std::uint32_t& register32(std::uintptr_t address) {
  return *reinterpret_cast<volatile std::uint32_t*>(address);
}

// Changes the bits `clear` of the 32-bit register at `address` to those of `set`, by reading, modifying and
// writing it: not atomic, so only where nothing else writes the register meanwhile (configuration at start-up).
inline void modify32(std::uintptr_t address, std::uint32_t clear, std::uint32_t set) {
  register32(address) = (register32(address) & ~clear) | set;
}

// The 8-bit register at `address` (the NVIC's priority fields are byte-addressable).
inline volatile std::uint8_t& register8(std::uintptr_t address) {
  return *reinterpret_cast<volatile std::uint8_t*>(address);
}

// Waits until every memory access before it has completed, and refetches the instructions after it: needed after
// writes that change how later instructions run (enabling the FPU, relocating the vector table).
inline void synchronize() { asm volatile("dsb\n isb" ::: "memory"); }

}  // namespace duet::cortex_m
