#pragma once
// The clocks of the peripherals the Cortex-M4 uses (RM0436, RCC): each has an enable bit in one of the MCU's
// MC_xxxENSETR registers, whose write-one-to-set form turns it on with a single store, so that enabling a clock never
// undoes another core's change to the same register. The clock tree itself (PLLs, dividers) is Linux's and the boot
// loader's: duet only switches on what it uses.

#include <cstdint>

#include "duet/cortex_m/registers.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t rcc_base = 0x5000'0000;

// A peripheral's clock: the offset of its MC_xxxENSETR register and its bit there.
struct PeripheralClock {
  std::uint32_t set_register;
  std::uint32_t bit;
};

namespace clock {
inline constexpr std::uint32_t apb1 = 0xA80, apb2 = 0xA88, ahb2 = 0xA98, ahb3 = 0xAA0, ahb4 = 0xAA8;
inline constexpr PeripheralClock tim2{apb1, 0}, tim4{apb1, 2}, tim5{apb1, 3}, tim7{apb1, 5};
inline constexpr PeripheralClock tim1{apb2, 0}, spi5{apb2, 10};
inline constexpr PeripheralClock dma2{ahb2, 1}, dmamux{ahb2, 2}, adc12{ahb2, 5};
inline constexpr PeripheralClock hsem{ahb3, 11}, ipcc{ahb3, 12};
// GPIOA .. GPIOK: port 0 is A.
constexpr PeripheralClock gpio(unsigned port) { return {ahb4, port}; }
}  // namespace clock

class Rcc {
 public:
  explicit constexpr Rcc(std::uintptr_t base = rcc_base) : base_(base) {}

  void enable(PeripheralClock clock) const { cortex_m::register32(base_ + clock.set_register) = 1U << clock.bit; }

 private:
  std::uintptr_t base_;
};

}  // namespace duet::stm32mp15
