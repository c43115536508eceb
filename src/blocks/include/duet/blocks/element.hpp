#pragma once
// The element types blocks compute with, and the bit-level facts about floating point that the blocks rely on.
//
// Blocks promise that the host interpreter and the generated firmware compute bit-identical results by calling the same
// functions. That holds only for IEEE 754 arithmetic rounded to nearest with no fused multiply-add: duet_blocks adds
// -ffp-contract=off to everything that uses it, because GCC otherwise fuses a multiply() and an add() into one
// Cortex-M4 VFMA after inlining, which rounds once instead of twice. NaNs are the exception: which NaN (sign, payload)
// an operation produces differs between the PC and the Cortex-M4, so only "it is a NaN" is the same on both.

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace duet::blocks {

static_assert(std::numeric_limits<float>::is_iec559 && std::numeric_limits<double>::is_iec559,
              "blocks assume IEEE 754 binary32 float and binary64 double");

// The elements of the block library are double, float, the 8- to 32-bit integers and bool. The concepts below accept
// every integer type (64-bit ones too) because convert and element_at need std::int64_t internally.
template <typename T>
concept Floating = std::is_same_v<T, float> || std::is_same_v<T, double>;

template <typename T>
concept Integer = std::is_integral_v<T> && !std::is_same_v<T, bool>;

// What arithmetic accepts: bool is a truth value, not a number, and goes through logic() instead.
template <typename T>
concept Number = Floating<T> || Integer<T>;

template <typename T>
concept Element = Number<T> || std::is_same_v<T, bool>;

namespace detail {

template <Floating T>
using FloatBits = std::conditional_t<sizeof(T) == sizeof(std::uint32_t), std::uint32_t, std::uint64_t>;

template <Floating T>
inline constexpr FloatBits<T> sign_mask = FloatBits<T>{1} << (sizeof(T) * 8U - 1U);

// The sign bit, also for -0.0 and NaNs, where comparisons cannot see it.
template <Floating T>
constexpr bool sign_bit(T value) {
  return (std::bit_cast<FloatBits<T>>(value) & sign_mask<T>) != 0;
}

// value != value, spelled with bits so that lints do not take it for a mistake: all exponent bits set, fraction not 0.
template <Floating T>
constexpr bool is_nan(T value) {
  return (std::bit_cast<FloatBits<T>>(value) & ~sign_mask<T>) >
         std::bit_cast<FloatBits<T>>(std::numeric_limits<T>::infinity());
}

// |value| as IEEE 754's abs(): -0.0 becomes +0.0 and a NaN stays a NaN, positive.
template <Floating T>
constexpr T clear_sign_bit(T value) {
  return std::bit_cast<T>(static_cast<FloatBits<T>>(std::bit_cast<FloatBits<T>>(value) & ~sign_mask<T>));
}

}  // namespace detail
}  // namespace duet::blocks
