#pragma once
// The EXTI's configurable lines 0-15 for the Cortex-M4 (RM0436, EXTI): a GPIO pin routed to its line, rising and/or
// falling edges, the line's interrupt unmasked for CPU2 (the M4); every line 0-15 has an interrupt of its own (EXTI8
// is IRQ 66: the IMU's INT on PE8). Rising and falling edges have separate pending registers, both cleared by
// writing one. The routing and edge registers are Linux's EXTI driver's too (other lines): connect() changes them
// holding the EXTI hardware semaphore (hsem.hpp). Register level, no HAL; `base` is the block's address (a fake
// register file in the PC's tests).

#include <cstdint>

#include "duet/cortex_m/registers.hpp"
#include "duet/stm32mp15/hsem.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t exti_base = 0x5000'D000;

class Exti {
 public:
  static constexpr std::uint32_t rtsr1 = 0x00, ftsr1 = 0x04, rpr1 = 0x0C, fpr1 = 0x10, exticr1 = 0x60, c2imr1 = 0xC0;

  // `hsem`: the hardware semaphores (a fake register file in the PC's tests).
  explicit constexpr Exti(std::uintptr_t base = exti_base, Hsem hsem = Hsem{}) : base_(base), hsem_(hsem) {}

  // Line `line` (0-15) takes pin `line` of GPIO port `port` (0 = A) and interrupts the M4 on the edges asked.
  // Start-up only. False, nothing changed, when the EXTI's semaphore was not to be had.
  [[nodiscard]] bool connect(unsigned line, unsigned port, bool rising, bool falling) const {
    const std::uint32_t route = exticr1 + 4U * (line / 4U);
    const unsigned shift = 8U * (line % 4U);
    const bool changed = hsem_.holding(semaphore::exti, [&] {
      modify(route, 0xFFU << shift, (port & 0xFFU) << shift);
      modify(rtsr1, 1U << line, rising ? 1U << line : 0U);
      modify(ftsr1, 1U << line, falling ? 1U << line : 0U);
    });
    if (!changed) return false;
    acknowledge(line);              // an edge from before is no event
    modify(c2imr1, 0, 1U << line);  // the M4's own mask: Linux writes C1IMR1
    return true;
  }

  // In the line's interrupt: clears both pending flags (write one to clear; the other lines' stay).
  void acknowledge(unsigned line) const {
    write(rpr1, 1U << line);
    write(fpr1, 1U << line);
  }
  [[nodiscard]] bool rose(unsigned line) const { return (read(rpr1) & 1U << line) != 0; }
  [[nodiscard]] bool fell(unsigned line) const { return (read(fpr1) & 1U << line) != 0; }

 private:
  [[nodiscard]] std::uint32_t read(std::uint32_t offset) const { return cortex_m::register32(base_ + offset); }
  void write(std::uint32_t offset, std::uint32_t value) const { cortex_m::register32(base_ + offset) = value; }
  void modify(std::uint32_t offset, std::uint32_t clear, std::uint32_t set_bits) const {
    cortex_m::modify32(base_ + offset, clear, set_bits);
  }

  std::uintptr_t base_;
  Hsem hsem_;
};

}  // namespace duet::stm32mp15
