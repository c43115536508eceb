#pragma once
// Arithmetic on one element type, defined for every input so that simulation and firmware agree even where C++ would
// have undefined behaviour.
//
// Integers wrap as two's complement (as Simulink does with saturation off): the operation runs in an unsigned type at
// least as wide as T, where wrapping is defined, and the result is cast back (modular since C++20). Division truncates
// toward zero, x / 0 is 0 and the most negative value / -1 wraps to itself. Floating point is the plain IEEE 754
// operator (x / 0.0 is an infinity or NaN). bool is not a number here. All functions are pure and interrupt-safe.

#include <type_traits>

#include "duet/blocks/element.hpp"

namespace duet::blocks {
namespace detail {

// Small integers are promoted to int before an operator applies, and int overflow is undefined: uint16 * uint16 can
// exceed INT_MAX. unsigned int and wider unsigned types are never promoted, so they wrap.
template <Integer T>
using WrapType = std::conditional_t<(sizeof(T) < sizeof(unsigned)), unsigned, std::make_unsigned_t<T>>;

template <Integer T>
constexpr WrapType<T> to_wrap(T value) {
  return static_cast<WrapType<T>>(value);
}

}  // namespace detail

template <Number T>
constexpr T add(T a, T b) {
  if constexpr (Integer<T>) {
    return static_cast<T>(detail::to_wrap(a) + detail::to_wrap(b));
  } else {
    return a + b;
  }
}

template <Number T>
constexpr T subtract(T a, T b) {
  if constexpr (Integer<T>) {
    return static_cast<T>(detail::to_wrap(a) - detail::to_wrap(b));
  } else {
    return a - b;
  }
}

template <Number T>
constexpr T multiply(T a, T b) {
  if constexpr (Integer<T>) {
    return static_cast<T>(detail::to_wrap(a) * detail::to_wrap(b));
  } else {
    return a * b;
  }
}

// -a; for unsigned T that is 2^N - a, for the most negative signed value it is that value again.
template <Number T>
constexpr T negate(T a) {
  if constexpr (Integer<T>) {
    return static_cast<T>(detail::WrapType<T>{0} - detail::to_wrap(a));
  } else {
    return -a;
  }
}

template <Number T>
constexpr T divide(T a, T b) {
  if constexpr (Integer<T>) {
    if (b == T{0}) return T{0};  // a controller must keep running, so this needs a defined answer
    if constexpr (std::is_signed_v<T>) {
      if (b == T{-1}) return negate(a);  // the only quotient that overflows: min / -1
    }
    return static_cast<T>(a / b);  // small types are promoted to int, where no quotient overflows
  } else {
    return a / b;
  }
}

// Simulink's Gain block: y = k * u, in that operand order (it matters only for which NaN comes out).
template <Number T>
constexpr T gain(T u, T k) {
  return multiply(k, u);
}

}  // namespace duet::blocks
