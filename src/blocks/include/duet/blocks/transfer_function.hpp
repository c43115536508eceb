#pragma once
// A discrete transfer function of order N (Simulink's Discrete Transfer Fcn), in direct form II transposed:
//
//          b0 + b1 z^-1 + ... + bN z^-N
//   H(z) = ----------------------------      numerator b0..bN and denominator a0..aN, highest power of z first,
//          a0 + a1 z^-1 + ... + aN z^-N      N + 1 values each (pad a lower-order numerator with zeros)
//
// The coefficients are normalised by a0 where they are used, every call, so that they can be tuned live (a0 = 1
// divides exactly and changes nothing). With b'i = divide(b[i], a[0]) and a'i = divide(a[i], a[0]):
//   y        = add(multiply(b'0, u), state[0])
//   state[i] = subtract(add(state[i + 1], multiply(b'(i+1), u)), multiply(a'(i+1), y))   for i = 0 .. N - 2
//   state[N - 1] = subtract(multiply(b'N, u), multiply(a'N, y))
// update() computes the states in increasing i, each from the previous step's state[i + 1], with y recomputed as
// output() computes it. state starts as the aggregate-initialised values (zeros: the system at rest).
// Preconditions: a[0] != 0 (otherwise the coefficients become infinities or NaNs); the arrays hold N + 1 values.
// Not interrupt-safe: one task owns the block.

#include <cstddef>

#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/element.hpp"

namespace duet::blocks {
namespace detail {

// The kernels for an order n known at run time (the simulation's interpreter calls them; the block below with N).
template <Floating T>
constexpr T transfer_function_output(const T* state, std::size_t /*n*/, T u, const T* numerator, const T* denominator) {
  return add(multiply(divide(numerator[0], denominator[0]), u), state[0]);
}

template <Floating T>
constexpr void transfer_function_update(T* state, std::size_t n, T u, const T* numerator, const T* denominator) {
  const T y = transfer_function_output(state, n, u, numerator, denominator);
  for (std::size_t i = 0; i < n; ++i) {
    const T b = divide(numerator[i + 1], denominator[0]);
    const T a = divide(denominator[i + 1], denominator[0]);
    const T feedforward = i + 1 < n ? add(state[i + 1], multiply(b, u)) : multiply(b, u);
    state[i] = subtract(feedforward, multiply(a, y));
  }
}

}  // namespace detail

template <Floating T, std::size_t N>
struct DiscreteTransferFunction {
  static_assert(N >= 1, "DiscreteTransferFunction: order N >= 1 (a gain is the Gain block)");

  T state[N];

  [[nodiscard]] constexpr T output(T u, const T* numerator, const T* denominator) const {
    return detail::transfer_function_output(state, N, u, numerator, denominator);
  }

  constexpr void update(T u, const T* numerator, const T* denominator) {
    detail::transfer_function_update(state, N, u, numerator, denominator);
  }
};

}  // namespace duet::blocks
