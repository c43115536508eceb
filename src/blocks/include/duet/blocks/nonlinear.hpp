#pragma once
// Saturation, absolute value and selection (Simulink's Saturation, Abs and Switch). Pure and interrupt-safe.

#include <limits>
#include <type_traits>

#include "duet/blocks/element.hpp"

namespace duet::blocks {

// Limits u to [lower, upper]: u > upper gives upper, u < lower gives lower, anything else (a NaN too: both
// comparisons are false) gives u. Precondition: lower <= upper; if not, upper wins for u > upper and lower for u <
// lower.
template <Number T>
constexpr T saturate(T u, T lower, T upper) {
  if (u > upper) return upper;
  if (u < lower) return lower;
  return u;
}

// |u|. Floating point as IEEE 754 defines it: |-0.0| = +0.0 and |NaN| is a NaN. The most negative integer has no
// positive counterpart; it saturates to the maximum (Simulink's Abs with saturation on), not wrapping to itself.
template <Number T>
constexpr T absolute(T u) {
  if constexpr (Floating<T>) {
    // The compiler's own |u|, which clears the sign bit and nothing else (NaNs too), as detail::clear_sign_bit does,
    // in one instruction (VABS) where the bit operations take three. GCC and Clang evaluate it in constant expressions.
    if constexpr (std::is_same_v<T, float>) {
      return __builtin_fabsf(u);
    } else {
      return __builtin_fabs(u);
    }
  } else if constexpr (std::is_signed_v<T>) {
    if (u == std::numeric_limits<T>::min()) return std::numeric_limits<T>::max();
    return u < T{0} ? static_cast<T>(-u) : u;  // -u is computed in int for small types; it fits T now
  } else {
    return u;
  }
}

// Simulink's Switch with a boolean control input: on when condition holds, off otherwise.
template <Element T>
constexpr T select(bool condition, T on, T off) {
  return condition ? on : off;
}

}  // namespace duet::blocks
