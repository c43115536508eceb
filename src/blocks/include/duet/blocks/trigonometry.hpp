#pragma once
// atan2 and angle-unit conversion without the C library (the firmware links without it), in float and double.
// Pure and interrupt-safe.
//
// Method. Special values first: a NaN gives a NaN. Then the angle is folded into the first octant: with a = |x| and
// b = |y|, z = min(a, b) / max(a, b) lies in [0, 1] (0/0 is taken as 0, inf/inf as 1), and
//   atan2(y, x) = ±(offset ± atan(z))   where offset is 0, pi/2 or pi depending on whether a < b and on x's sign bit.
// atan(z) is reduced once more around the nearest c = k/8 (k = 0..8) by atan(z) = atan(c) + atan(t) with
//   t = (z - c) / (1 + z * c),   |t| <= 1/16,
// and atan(t) is its Taylor series t - t^3/3 + t^5/5 - ..., cut off where the next term is far below half an ulp:
// after t^5 for float (next term <= (1/16)^7 / 7 = 5e-10) and after t^13 for double (next <= (1/16)^15 / 15 = 6e-20).
// The constants offset ± atan(k/8) come precomputed and rounded once to T (atan(k/8) and pi were computed to 40 digits
// with mpmath, kept to 21), so the result is one rounded constant plus a small, almost exact series: the error stays
// below about 3e-7 rad in float and 1e-15 rad in double (the tests check 4e-7 and 1e-13 against the C library).
//
// Special values are those of C's atan2: atan2(±0, +0) = ±0, atan2(±0, -0) = ±pi, atan2(±0, x < 0) = ±pi,
// atan2(y != 0, ±0) = ±pi/2, atan2(±inf, +inf) = ±pi/4, atan2(±inf, -inf) = ±3pi/4.

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "duet/blocks/element.hpp"

namespace duet::blocks {
namespace detail {

inline constexpr double pi = 3.14159265358979323846264;
inline constexpr double degrees_per_radian = 57.2957795130823208767982;    // 180 / pi
inline constexpr double radians_per_degree = 0.0174532925199432957692369;  // pi / 180

inline constexpr std::size_t atan_table_size = 9;  // atan(k / 8) for k = 0..8

inline constexpr std::array<double, atan_table_size> atan_of_eighths = {
    0.0,
    0.124354994546761435031355,
    0.244978663126864154172083,
    0.358770670270572220395920,
    0.463647609000806116214256,
    0.558599315343562435971508,
    0.643501108793284386802809,
    0.718829999621624505417014,
    0.785398163397448309615661,
};

// offset + sign * atan(k / 8) for the four ways the octant folds back, indexed by (x negative) * 2 + (|y| > |x|):
//   |y| <= |x|, x >= 0:  atan(z)            |y| <= |x|, x < 0:  pi - atan(z)
//   |y| > |x|,  x >= 0:  pi/2 - atan(z)     |y| > |x|,  x < 0:  pi/2 + atan(z)
// Computed in double and rounded to T once.
inline constexpr std::array<double, 4> octant_offsets = {0.0, pi / 2, pi, pi / 2};
inline constexpr std::array<bool, 4> octant_subtracts = {false, true, true, false};

template <Floating T>
constexpr std::array<std::array<T, atan_table_size>, 4> make_atan2_bases() {
  std::array<std::array<T, atan_table_size>, 4> bases{};
  for (std::size_t octant = 0; octant < 4; ++octant) {
    for (std::size_t k = 0; k < atan_table_size; ++k) {
      const double atan_c = octant_subtracts[octant] ? -atan_of_eighths[k] : atan_of_eighths[k];
      bases[octant][k] = static_cast<T>(octant_offsets[octant] + atan_c);
    }
  }
  return bases;
}

template <Floating T>
inline constexpr auto atan2_bases = make_atan2_bases<T>();

// atan(t) for |t| <= 1/16: t + t^3 * (-1/3 + t^2 * (1/5 - t^2 * (1/7 - ...))), Horner from the highest term.
template <Floating T>
constexpr T atan_series(T t) {
  constexpr int highest_power = std::is_same_v<T, float> ? 5 : 13;
  const T t2 = t * t;
  T sum{0};
  for (int power = highest_power; power >= 3; power -= 2) {
    const T coefficient = static_cast<T>((power % 4 == 1 ? 1.0 : -1.0) / power);  // +-1/power, rounded once
    sum = coefficient + t2 * sum;
  }
  return t + (t * t2) * sum;
}

template <Floating T>
constexpr T atan2_of(T y, T x) {
  if (is_nan(x) || is_nan(y)) return std::numeric_limits<T>::quiet_NaN();  // the same NaN on every platform
  const T a = clear_sign_bit(x);
  const T b = clear_sign_bit(y);
  const bool steep = b > a;  // |y| > |x|: the angle from the y axis is the smaller one
  const T numerator = steep ? a : b;
  const T denominator = steep ? b : a;
  T z{0};  // 0/0: both zero, the angle is 0 or pi
  if (denominator != T{0}) z = numerator == denominator ? T{1} : numerator / denominator;  // inf/inf counts as 1
  const int k = static_cast<int>(z * T{8} + static_cast<T>(0.5));  // nearest eighth; z <= 1, so k <= 8
  const T c = static_cast<T>(k) / T{8};                            // exact
  const T t = (z - c) / (T{1} + z * c);  // z - c is exact: z and c are within a factor 2 of each other (or c is 0)
  const std::size_t octant = (sign_bit(x) ? 2U : 0U) + (steep ? 1U : 0U);
  const T series = atan_series(t);
  const T base = atan2_bases<T>[octant][static_cast<std::size_t>(k)];
  const T angle = octant_subtracts[octant] ? base - series : base + series;
  return sign_bit(y) ? -angle : angle;
}

}  // namespace detail

constexpr float atan2(float y, float x) { return detail::atan2_of(y, x); }
constexpr double atan2(double y, double x) { return detail::atan2_of(y, x); }

// One multiplication by 180/pi or pi/180 rounded to T, so degrees(radians(v)) may differ from v in the last bit.
constexpr float degrees(float angle_rad) { return angle_rad * static_cast<float>(detail::degrees_per_radian); }
constexpr double degrees(double angle_rad) { return angle_rad * detail::degrees_per_radian; }
constexpr float radians(float angle_deg) { return angle_deg * static_cast<float>(detail::radians_per_degree); }
constexpr double radians(double angle_deg) { return angle_deg * detail::radians_per_degree; }

}  // namespace duet::blocks
