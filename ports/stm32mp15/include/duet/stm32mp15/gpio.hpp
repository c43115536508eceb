#pragma once
// A GPIO port (RM0436, GPIO): pins configured as outputs, inputs or alternate functions at start-up, then driven
// through BSRR (one write sets or clears a pin, so an interrupt between tasks never undoes another pin's change) and
// read through IDR. Register level, no HAL; `base` is the port's address (a fake register file in the PC's tests).
// Configuration reads, modifies and writes registers that Linux's pin controller writes too (other pins of the same
// port): it holds the GPIO hardware semaphore meanwhile (hsem.hpp), and fails, nothing changed, when that is not to be
// had. Configure at start-up, before interrupts are on.

#include <cstdint>

#include "duet/cortex_m/registers.hpp"
#include "duet/stm32mp15/hsem.hpp"

namespace duet::stm32mp15 {

// GPIOA .. GPIOK: port 0 is A.
inline constexpr std::uintptr_t gpio_base(unsigned port) { return 0x5000'2000U + 0x1000U * port; }

enum class Pull : std::uint32_t { none = 0, up = 1, down = 2 };

class GpioPort {
 public:
  static constexpr std::uint32_t moder = 0x00, otyper = 0x04, ospeedr = 0x08, pupdr = 0x0C, idr = 0x10, odr = 0x14,
                                 bsrr = 0x18, afrl = 0x20, afrh = 0x24;

  // `hsem`: the hardware semaphores (a fake register file in the PC's tests).
  explicit constexpr GpioPort(std::uintptr_t base, Hsem hsem = Hsem{}) : base_(base), hsem_(hsem) {}

  [[nodiscard]] bool make_output(unsigned pin) const {
    return hsem_.holding(semaphore::gpio, [&] {
      modify(otyper, 1U << pin, 0);  // push-pull
      modify(moder, 3U << (2 * pin), 1U << (2 * pin));
    });
  }
  [[nodiscard]] bool make_input(unsigned pin, Pull pull) const {
    return hsem_.holding(semaphore::gpio, [&] {
      modify(pupdr, 3U << (2 * pin), static_cast<std::uint32_t>(pull) << (2 * pin));
      modify(moder, 3U << (2 * pin), 0);
    });
  }
  // The pin to a peripheral (timer channel, SPI): `function` is the AF number of the chip's datasheet.
  [[nodiscard]] bool make_alternate(unsigned pin, unsigned function) const {
    const std::uint32_t afr = pin < 8 ? afrl : afrh;
    const unsigned shift = 4 * (pin % 8);
    return hsem_.holding(semaphore::gpio, [&] {
      modify(afr, 0xFU << shift, (function & 0xFU) << shift);
      modify(moder, 3U << (2 * pin), 2U << (2 * pin));
    });
  }

  void set(unsigned pin, bool high) const { write(bsrr, high ? 1U << pin : 1U << (16 + pin)); }
  [[nodiscard]] bool read(unsigned pin) const { return (read_register(idr) & 1U << pin) != 0; }

 private:
  [[nodiscard]] std::uint32_t read_register(std::uint32_t offset) const { return cortex_m::register32(base_ + offset); }
  void write(std::uint32_t offset, std::uint32_t value) const { cortex_m::register32(base_ + offset) = value; }
  void modify(std::uint32_t offset, std::uint32_t clear, std::uint32_t set_bits) const {
    cortex_m::modify32(base_ + offset, clear, set_bits);
  }

  std::uintptr_t base_;
  Hsem hsem_;
};

}  // namespace duet::stm32mp15
