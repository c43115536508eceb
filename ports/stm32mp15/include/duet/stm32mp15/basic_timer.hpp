#pragma once
// TIM6/TIM7, the basic timers (RM0436, TIM6/TIM7): the executive's base rate comes from TIM7's update interrupt.
// Register level, no HAL; `base` is the block's address (a fake register file in the PC's tests). The timer's input
// clock is whatever Linux and the boot loader configured (docs/BOARD.md); the caller says what it is.

#include <cstdint>

#include "duet/cortex_m/registers.hpp"
#include "duet/stm32mp15/timer_counts.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t tim6_base = 0x4000'4000;
inline constexpr std::uintptr_t tim7_base = 0x4000'5000;

class BasicTimer {
 public:
  static constexpr std::uint32_t cr1 = 0x00, dier = 0x0C, sr = 0x10, egr = 0x14, cnt = 0x24, psc = 0x28, arr = 0x2C;
  static constexpr std::uint32_t counter_enable = 1U << 0U;     // CR1.CEN
  static constexpr std::uint32_t preload = 1U << 7U;            // CR1.ARPE
  static constexpr std::uint32_t update_interrupt = 1U << 0U;   // DIER.UIE
  static constexpr std::uint32_t update_flag = 1U << 0U;        // SR.UIF
  static constexpr std::uint32_t update_generation = 1U << 0U;  // EGR.UG

  explicit constexpr BasicTimer(std::uintptr_t base) : base_(base) {}

  // An update interrupt every `period_ns` of a `clock_hz` input clock; false (nothing touched) for a period the
  // 16-bit prescaler and counter cannot make, or one shorter than two counts.
  [[nodiscard]] bool start(std::uint64_t period_ns, std::uint32_t clock_hz) const {
    const TimeBase time_base = time_base_for(period_ns, clock_hz);
    if (!time_base.possible) return false;
    write(cr1, 0);
    write(psc, time_base.prescaler);
    write(arr, time_base.reload);
    write(cnt, 0);
    write(egr, update_generation);  // loads the prescaler now; it sets UIF, which is no tick
    write(sr, 0);
    write(dier, update_interrupt);
    write(cr1, counter_enable | preload);
    return true;
  }

  void stop() const {
    write(cr1, 0);
    write(dier, 0);
  }

  // In the interrupt handler: clears the update flag (write 0 to clear; the other flags are not ours).
  void acknowledge() const { write(sr, ~update_flag); }
  [[nodiscard]] std::uint32_t count() const { return read(cnt); }

 private:
  [[nodiscard]] std::uint32_t read(std::uint32_t offset) const { return cortex_m::register32(base_ + offset); }
  void write(std::uint32_t offset, std::uint32_t value) const { cortex_m::register32(base_ + offset) = value; }

  std::uintptr_t base_;
};

}  // namespace duet::stm32mp15
