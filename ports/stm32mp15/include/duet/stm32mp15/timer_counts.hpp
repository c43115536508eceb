#pragma once
// A timer's time base from a period (RM0436, TIM time base unit; the thesis' eq. A.1 and A.2): the counter counts at
// clock / (PSC + 1) and its period is ARR + 1 of those counts. Shared by the basic timers (TIM6/TIM7) and the
// general-purpose and advanced-control ones (TIM1-TIM5), which all have a 16-bit prescaler.

#include <cstdint>

namespace duet::stm32mp15 {

struct TimeBase {
  bool possible = false;
  std::uint32_t prescaler = 0;  // PSC
  std::uint32_t reload = 0;     // ARR
};

// The time base of `period_ns` from a `clock_hz` input clock, with the smallest prescaler that lets a 16-bit counter
// reach it (the finest steps of the period); not possible for a period the 16-bit prescaler and counter cannot
// make, or one shorter than two counts. A period that is no whole number of counts is shortened to one.
constexpr TimeBase time_base_for(std::uint64_t period_ns, std::uint32_t clock_hz) {
  if (period_ns > 1'000'000'000'000U) return {};  // 1000 s: no timer here is that slow
  // Whole seconds and the rest apart, so that no product overflows 64 bits.
  const std::uint64_t counts =
      period_ns / 1'000'000'000U * clock_hz + period_ns % 1'000'000'000U * clock_hz / 1'000'000'000U;
  if (counts < 2) return {};
  const std::uint64_t prescaler = (counts - 1) / 0x1'0000U;
  if (prescaler > 0xFFFF) return {};
  const std::uint64_t reload = counts / (prescaler + 1) - 1;
  return {true, static_cast<std::uint32_t>(prescaler), static_cast<std::uint32_t>(reload)};
}

}  // namespace duet::stm32mp15
