#pragma once
// The clocks of the peripherals the Cortex-M4 uses (RM0436, RCC): each has an enable bit in one of the MCU's
// MC_xxxENSETR registers, whose write-one-to-set form turns it on with a single store, so that enabling a clock never
// undoes another core's change to the same register. The clock tree itself (PLLs, dividers) is Linux's and the boot
// loader's: duet only switches on what it uses, and reads which kernel clock SPI5 was given.

#include <cstdint>
#include <string_view>

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

// Where SPI4 and SPI5's kernel clock comes from (RCC_SPI45CKSELR.SPI45SRC, values 0-4 in this order; the others
// switch it off).
enum class Spi45ClockSource : std::uint8_t { pclk2, pll4_q, hsi, csi, hse, off };

constexpr std::string_view name(Spi45ClockSource source) {
  switch (source) {
    case Spi45ClockSource::pclk2: return "pclk2";
    case Spi45ClockSource::pll4_q: return "pll4_q";
    case Spi45ClockSource::hsi: return "hsi";
    case Spi45ClockSource::csi: return "csi";
    case Spi45ClockSource::hse: return "hse";
    case Spi45ClockSource::off: break;
  }
  return "off";
}

// A kernel clock: its source and rate; 0 Hz when duet cannot tell the rate (PLL4, whose settings it does not read)
// or the clock is off.
struct KernelClock {
  Spi45ClockSource source;
  std::uint32_t hz;
};

class Rcc {
 public:
  static constexpr std::uint32_t hsicfgr = 0x18, apb2divr = 0x838, spi45ckselr = 0x8E0;
  static constexpr std::uint32_t hsi_hz = 64'000'000;  // HSI before HSIDIV
  static constexpr std::uint32_t csi_hz = 4'000'000;   // CSI, nominal

  explicit constexpr Rcc(std::uintptr_t base = rcc_base) : base_(base) {}

  void enable(PeripheralClock clock) const { cortex_m::register32(base_ + clock.set_register) = 1U << clock.bit; }

  // SPI4 and SPI5's kernel clock as the boot loader or Linux selected it. PCLK2 is the MCU clock (the M4's,
  // `mcu_clock_hz`) divided by APB2DIV; HSI is 64 MHz divided by HSIDIV; CSI 4 MHz; HSE the board's crystal
  // (`hse_hz`). Read at start-up: Linux may change the selection only while SPI4/5 are stopped.
  [[nodiscard]] KernelClock spi45_kernel_clock(std::uint32_t mcu_clock_hz, std::uint32_t hse_hz) const {
    switch (read(spi45ckselr) & 7U) {
      case 0: {
        const std::uint32_t apb2_divider = read(apb2divr) & 7U;  // 2^n up to 16: 4 and above divide by 16
        return {Spi45ClockSource::pclk2, mcu_clock_hz >> (apb2_divider < 4U ? apb2_divider : 4U)};
      }
      case 1: return {Spi45ClockSource::pll4_q, 0};
      case 2: return {Spi45ClockSource::hsi, hsi_hz >> (read(hsicfgr) & 3U)};
      case 3: return {Spi45ClockSource::csi, csi_hz};
      case 4: return {Spi45ClockSource::hse, hse_hz};
      default: return {Spi45ClockSource::off, 0};
    }
  }

 private:
  [[nodiscard]] std::uint32_t read(std::uint32_t offset) const { return cortex_m::register32(base_ + offset); }

  std::uintptr_t base_;
};

}  // namespace duet::stm32mp15
