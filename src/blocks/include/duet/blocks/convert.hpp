#pragma once
// Conversion between element types (Simulink's Data Type Conversion), defined for every input: out-of-range values
// saturate instead of being undefined behaviour, so simulation and firmware agree on them too.
//
//   same type            identity
//   to bool              u != 0 (a NaN is true)
//   from bool            0 or 1
//   floating -> integer  NaN is 0; otherwise truncated toward zero and saturated to the target's range (infinities too)
//   integer -> integer   saturated to the target's range
//   -> floating          rounded to nearest; a double beyond float's range becomes an infinity, as IEEE 754 says
//
// Pure and interrupt-safe. Every integer type up to 64 bits is accepted (element_at converts indexes to std::int64_t).

#include <limits>
#include <type_traits>

#include "duet/blocks/element.hpp"

namespace duet::blocks {
namespace detail {

// a < b for integers of any signedness, without the usual arithmetic conversions turning -1 into a huge unsigned value.
template <Integer A, Integer B>
constexpr bool integer_less(A a, B b) {
  if constexpr (std::is_signed_v<A> == std::is_signed_v<B>) {
    return a < b;  // both are promoted to the wider of the two, which holds both values
  } else if constexpr (std::is_signed_v<A>) {
    return a < A{0} || static_cast<std::make_unsigned_t<A>>(a) < b;
  } else {
    return b >= B{0} && a < static_cast<std::make_unsigned_t<B>>(b);
  }
}

// 2^exponent, exact in F for every exponent used here (at most 64).
template <Floating F>
constexpr F power_of_two(int exponent) {
  F result{1};
  for (int i = 0; i < exponent; ++i) result *= F{2};
  return result;
}

template <Integer To, Floating From>
constexpr To floating_to_integer(From u) {
  using Limits = std::numeric_limits<To>;
  if constexpr (!std::is_signed_v<To>) {
    // NaN, negative values and (-1, 0) all give 0: one comparison, false for a NaN, tells them apart.
    if (!(u > From{-1})) return To{0};
  } else {
    if (is_nan(u)) return To{0};
  }
  // One past the largest value is a power of two (2^digits), so it is exact in From, unlike the largest value itself:
  // int32's 2^31 - 1 rounds up to 2^31 in float.
  constexpr From past_max = power_of_two<From>(Limits::digits);
  if (u >= past_max) return Limits::max();
  if constexpr (std::is_signed_v<To>) {
    if (u <= -past_max) return Limits::min();  // -2^digits is the minimum itself
  }
  return static_cast<To>(u);  // (-1, 0) truncates to 0 by itself  // in range: the cast truncates toward zero
}

template <Integer To, Integer From>
constexpr To integer_to_integer(From u) {
  using Limits = std::numeric_limits<To>;
  if (integer_less(u, Limits::min())) return Limits::min();
  if (integer_less(Limits::max(), u)) return Limits::max();
  return static_cast<To>(u);
}

template <Floating To, Floating From>
constexpr To floating_to_floating(From u) {
  if constexpr (sizeof(To) >= sizeof(From)) {
    return static_cast<To>(u);  // widening is exact
  } else {
    // A double outside float's range makes static_cast undefined. IEEE 754 rounds it to an infinity from the midpoint
    // between float's largest value and 2^128 on (the tie goes to the even 2^128, i.e. to infinity), and to the largest
    // value below that.
    constexpr From largest = static_cast<From>(std::numeric_limits<To>::max());
    constexpr From overflow_threshold =
        largest + power_of_two<From>(std::numeric_limits<To>::max_exponent - std::numeric_limits<To>::digits - 1);
    if (u >= overflow_threshold) return std::numeric_limits<To>::infinity();
    if (u <= -overflow_threshold) return -std::numeric_limits<To>::infinity();
    if (u > largest) return std::numeric_limits<To>::max();
    if (u < -largest) return std::numeric_limits<To>::lowest();
    return static_cast<To>(u);  // in range (or NaN): rounded to nearest
  }
}

}  // namespace detail

template <typename To, typename From>
constexpr To convert(From u) {
  static_assert(Element<To> && Element<From>, "convert: element types are floating point, integers and bool");
  if constexpr (std::is_same_v<To, From>) {
    return u;
  } else if constexpr (std::is_same_v<To, bool>) {
    return u != From{0};
  } else if constexpr (std::is_same_v<From, bool>) {
    return u ? To{1} : To{0};
  } else if constexpr (Floating<To> && Floating<From>) {
    return detail::floating_to_floating<To>(u);
  } else if constexpr (Floating<To>) {
    return static_cast<To>(u);  // every integer up to 64 bits is below float's maximum
  } else if constexpr (Floating<From>) {
    return detail::floating_to_integer<To>(u);
  } else {
    return detail::integer_to_integer<To>(u);
  }
}

}  // namespace duet::blocks
