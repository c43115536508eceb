#pragma once
// Saturation, dead zone, absolute value, sign, minimum and maximum, and selection (Simulink's Saturation, Dead Zone,
// Abs, Sign, MinMax and Switch). Pure and interrupt-safe.

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

// Simulink's Dead Zone: 0 for start <= u <= end, u - end above end, u - start below start, tested in the order
// Simulink's code tests them (u > end, then u >= start). Inside the zone the output is +0.0, also for u = -0.0; a NaN
// fails both tests and gives u - start, a NaN. Floating point only: how the integer block overflows is an option of
// Simulink's that duet does not model. Precondition: start <= end; if not, u > end is tested first.
template <Floating T>
constexpr T dead_zone(T u, T start, T end) {
  if (u > end) return u - end;
  if (u >= start) return T{0};
  return u - start;
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

// -1, 0 or +1 as u is below, equal to or above 0 (Simulink's Sign). 0 and -0.0 give 0 (+0.0), and so does a NaN:
// both comparisons are false for it, so a NaN input never decides a direction. Unsigned u gives 0 or 1.
template <Number T>
constexpr T sign(T u) {
  if (u > T{0}) return T{1};
  if constexpr (std::is_signed_v<T>) {
    if (u < T{0}) return T{-1};
  }
  return T{0};
}

// The smaller and the larger of two values (Simulink's MinMax with two inputs). Floating point follows IEEE 754's
// minNum and maxNum: if exactly one operand is a NaN the other one is returned, so a single NaN input does not reach
// the output; two NaNs give a NaN (b). Equal operands give a, also +0.0 and -0.0 (minimum(+0.0, -0.0) is +0.0).
template <Number T>
constexpr T minimum(T a, T b) {
  if constexpr (Floating<T>) {
    if (detail::is_nan(a)) return b;
  }
  return b < a ? b : a;  // false for a NaN b: a is returned
}

template <Number T>
constexpr T maximum(T a, T b) {
  if constexpr (Floating<T>) {
    if (detail::is_nan(a)) return b;
  }
  return b > a ? b : a;  // false for a NaN b: a is returned
}

// Simulink's Switch with a boolean control input: on when condition holds, off otherwise.
template <Element T>
constexpr T select(bool condition, T on, T off) {
  return condition ? on : off;
}

}  // namespace duet::blocks
