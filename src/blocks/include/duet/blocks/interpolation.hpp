#pragma once
// A 1-D table with explicit breakpoints (Simulink's 1-D Lookup Table, n-D Lookup Table with one dimension, binary
// index search). Pure and interrupt-safe.
//
// The steps are those of Simulink's generated code, so that both round alike: the input is placed among the
// breakpoints (below or at the first, between two, at or above the last); linear interpolation then computes the
// fraction f = (u - b[i]) / (b[i+1] - b[i]) and y = (t[i+1] - t[i]) * f + t[i], each operation rounded once.

#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/blocks/element.hpp"

namespace duet::blocks {

// linear: Simulink's "Linear point-slope"; nearest: the closest breakpoint's value, the upper one when u is midway;
// flat: the value at the breakpoint at or below u; above: the value at the breakpoint at or above u.
enum class InterpolationMethod : std::uint8_t { linear, nearest, flat, above };
// clip: below the first breakpoint as at the first, above the last as at the last; linear: the end segment's line
// continued (linear interpolation only; the other methods always clip).
enum class Extrapolation : std::uint8_t { clip, linear };

namespace detail {

// The i with b[i] <= u < b[i + 1], for b[0] < u < b[n - 1] and strictly increasing b: a binary search, at most
// log2(n) + 1 steps, whatever the values (unsorted breakpoints give some i, never one outside the table).
template <Floating T>
constexpr std::size_t segment_of(std::span<const T> breakpoints, T u) {
  std::size_t left = 0;
  std::size_t right = breakpoints.size() - 1;
  while (right - left > 1) {
    const std::size_t middle = left + (right - left) / 2;
    if (u < breakpoints[middle]) {
      right = middle;
    } else {
      left = middle;
    }
  }
  return left;
}

template <Floating T>
constexpr T interpolate_linear(Extrapolation extrapolation, std::span<const T> breakpoints, std::span<const T> table,
                               T u) {
  const std::size_t last = breakpoints.size() - 1;
  std::size_t i = 0;
  T fraction = T{0};
  if (u <= breakpoints[0]) {
    if (extrapolation == Extrapolation::linear) fraction = (u - breakpoints[0]) / (breakpoints[1] - breakpoints[0]);
  } else if (u < breakpoints[last]) {
    i = segment_of(breakpoints, u);
    fraction = (u - breakpoints[i]) / (breakpoints[i + 1] - breakpoints[i]);
  } else {  // at or above the last breakpoint, or a NaN
    i = last - 1;
    fraction =
        extrapolation == Extrapolation::linear ? (u - breakpoints[i]) / (breakpoints[last] - breakpoints[i]) : T{1};
  }
  return (table[i + 1] - table[i]) * fraction + table[i];
}

// The index of the table value a method without interpolation gives.
template <Floating T>
constexpr std::size_t index_of(InterpolationMethod method, std::span<const T> breakpoints, T u) {
  const std::size_t last = breakpoints.size() - 1;
  if (u <= breakpoints[0]) return 0;
  if (!(u < breakpoints[last])) return last;  // at or above the last breakpoint, or a NaN
  const std::size_t i = segment_of(breakpoints, u);
  if (method == InterpolationMethod::nearest) {
    return breakpoints[i + 1] - u <= u - breakpoints[i] ? i + 1 : i;
  }
  if (method == InterpolationMethod::above) return u > breakpoints[i] ? i + 1 : i;
  return i;
}

}  // namespace detail

// The table's value at u. A NaN u is placed above the last breakpoint, as Simulink's comparisons place it: clipped
// linear interpolation gives (t[n-1] - t[n-2]) * 1 + t[n-2], the other methods t[n-1], linear extrapolation a NaN.
// Infinite inputs are clipped, or extrapolated to an infinity (a NaN where the end segment is flat: 0 * inf).
// Preconditions: breakpoints and table have the same size, at least 2, and the breakpoints increase strictly; a table
// of another size, or of fewer than 2, gives T{} (the model's checker refuses them).
template <Floating T>
constexpr T interpolate(InterpolationMethod method, Extrapolation extrapolation, std::span<const T> breakpoints,
                        std::span<const T> table, T u) {
  if (breakpoints.size() < 2 || table.size() != breakpoints.size()) return T{};
  if (method == InterpolationMethod::linear) return detail::interpolate_linear(extrapolation, breakpoints, table, u);
  return table[detail::index_of(method, breakpoints, u)];
}

}  // namespace duet::blocks
