#pragma once
// Sources that count base steps instead of reading a clock (Simulink's Step and Pulse Generator, sample based), so a
// model's signals depend on the step count alone and simulation and firmware produce them alike. k is the number of
// steps since the start (0 in the first step); StepCounter provides it for a model that has no clock of its own.
// Functions are pure and interrupt-safe; StepCounter, like every state block, has one owner task.

#include <cstdint>
#include <limits>

#include "duet/blocks/element.hpp"

namespace duet::blocks {

// initial for k < step_k, final_value from step k = step_k on (step_k = 0: final_value from the start).
template <Number T>
constexpr T step(std::uint32_t k, std::uint32_t step_k, T initial, T final_value) {
  return k < step_k ? initial : final_value;
}

// amplitude while k >= delay and (k - delay) % period < width, otherwise 0: the pulse starts at step delay, lasts width
// steps and repeats every period steps. width >= period gives amplitude from delay on; width 0 or period 0 gives 0.
// A square wave is width = period / 2.
template <Number T>
constexpr T pulse(std::uint32_t k, std::uint32_t period, std::uint32_t width, std::uint32_t delay, T amplitude) {
  if (period == 0 || k < delay) return T{0};
  return (k - delay) % period < width ? amplitude : T{0};
}

// Counts the steps since the start: output() is k, update() adds 1 and stops at the largest std::uint32_t (after
// about 49.7 days at 1 kHz) instead of wrapping to 0, so the sources above never restart.
struct StepCounter {
  std::uint32_t k;

  [[nodiscard]] constexpr std::uint32_t output() const { return k; }
  constexpr void update() {
    if (k != std::numeric_limits<std::uint32_t>::max()) k = k + 1U;
  }
};

}  // namespace duet::blocks
