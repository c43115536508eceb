#pragma once
// Averages: the mean of a vector (Simulink's Mean) and the moving average over the last N steps (Simulink's Moving
// Average, sliding window). Both sum afresh every call, oldest to newest, instead of keeping a running sum that would
// accumulate rounding errors. mean is pure; MovingAverage is not interrupt-safe (one task owns it).

#include <cstddef>
#include <cstdint>
#include <limits>

#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/convert.hpp"
#include "duet/blocks/element.hpp"

namespace duet::blocks {

// divide(u[0] + u[1] + ... + u[n - 1], convert<T>(n)), the sum left to right from u[0] (acc = add(acc, u[i])); n == 0
// gives 0. Precondition: u holds n values.
template <Floating T>
constexpr T mean(const T* u, std::size_t n) {
  if (n == 0) return T{0};
  T acc = u[0];
  for (std::size_t i = 1; i < n; ++i) acc = add(acc, u[i]);
  return divide(acc, convert<T>(n));
}

// The mean of the last N inputs, the current one included. window is a ring of N slots: slot next % N holds the input
// of N steps ago, which has left the window, and the slots after it (next + 1, ..., next + N - 1, modulo N) hold the
// previous N - 1 inputs, oldest first. So
//   output(u) = divide(((window[next + 1] + window[next + 2]) + ... + window[next + N - 1]) + u, N)   (indexes mod N)
// summed left to right from window[next + 1] (for N = 1 it is divide(u, 1) = u), and update(u) writes u to slot
// next % N and advances next to (next % N + 1) % N. Before N inputs have arrived the missing ones are the
// aggregate-initialised values: MovingAverage<float, 4>{} starts from zeros, so its first output is u / 4; to start
// from a value v, initialise every slot with v. next is taken modulo N, so any value is safe.
namespace detail {

// The kernels for a window of n known at run time (the simulation's interpreter calls them; the block below with N).
template <Floating T>
constexpr T moving_average_output(const T* window, std::uint32_t next, std::size_t n, T u) {
  const std::size_t oldest = static_cast<std::size_t>(next) % n;
  T acc = u;
  if (n > 1) {
    acc = window[(oldest + 1U) % n];
    for (std::size_t i = 2; i < n; ++i) acc = add(acc, window[(oldest + i) % n]);
    acc = add(acc, u);
  }
  return divide(acc, convert<T>(n));
}

template <Floating T>
constexpr void moving_average_update(T* window, std::uint32_t& next, std::size_t n, T u) {
  const std::size_t oldest = static_cast<std::size_t>(next) % n;
  window[oldest] = u;
  next = static_cast<std::uint32_t>((oldest + 1U) % n);
}

}  // namespace detail

template <Floating T, std::size_t N>
struct MovingAverage {
  static_assert(N >= 1 && N <= std::numeric_limits<std::uint32_t>::max(), "MovingAverage: 1 <= N < 2^32");

  T window[N];
  std::uint32_t next;

  [[nodiscard]] constexpr T output(T u) const { return detail::moving_average_output(window, next, N, u); }
  constexpr void update(T u) { detail::moving_average_update(window, next, N, u); }
};

}  // namespace duet::blocks
