#pragma once
// Packing elements into bytes and back (Simulink's Byte Pack and Byte Unpack), for messages and buffers whose byte
// order is fixed whatever the processor's own. Pure; interrupt-safe as long as no other task writes the bytes
// meanwhile.
//
//   integers      their two's complement bits, sizeof(T) bytes
//   float, double their IEEE 754 bits (binary32, binary64), via std::bit_cast, so NaN payloads and -0.0 survive
//   bool          one byte, 0 or 1; unpacking takes any byte other than 0 as true
//
// Endian::little puts the least significant byte first, Endian::big the most significant one. A value that is not one
// of the two enumerators counts as little.

#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "duet/blocks/element.hpp"

namespace duet::blocks {

enum class Endian : std::uint8_t { little, big };

namespace detail {

// The unsigned type whose bits are the packed bytes.
template <Element T>
struct PackedBits {
  using type = std::make_unsigned_t<T>;
};
template <>
struct PackedBits<bool> {
  using type = std::uint8_t;
};
template <Floating T>
struct PackedBits<T> {
  using type = FloatBits<T>;
};

// Bits widened so that shifts and masks never promote to (signed) int.
template <typename Bits>
using ShiftBits = std::conditional_t<(sizeof(Bits) < sizeof(unsigned)), unsigned, Bits>;

// Where the byte of significance `significance` (0: least significant) goes among `size` bytes.
constexpr std::size_t byte_position(std::size_t significance, std::size_t size, Endian endian) {
  return endian == Endian::big ? size - 1U - significance : significance;
}

}  // namespace detail

// Writes sizeof(T) bytes of value to bytes[0..sizeof(T) - 1] (1 for bool). Precondition: bytes holds that many.
template <Element T>
constexpr void pack(T value, Endian endian, std::uint8_t* bytes) {
  using Bits = typename detail::PackedBits<T>::type;
  Bits bits{};
  if constexpr (std::is_same_v<T, bool>) {
    bits = value ? Bits{1} : Bits{0};
  } else if constexpr (Floating<T>) {
    bits = std::bit_cast<Bits>(value);
  } else {
    bits = static_cast<Bits>(value);  // modular: the two's complement bits
  }
  const auto wide = static_cast<detail::ShiftBits<Bits>>(bits);
  for (std::size_t significance = 0; significance < sizeof(Bits); ++significance) {
    bytes[detail::byte_position(significance, sizeof(Bits), endian)] =
        static_cast<std::uint8_t>((wide >> (8U * significance)) & 0xFFU);
  }
}

// Reads the sizeof(T) bytes (1 for bool) that pack() writes. Precondition: bytes holds that many.
template <Element T>
[[nodiscard]] constexpr T unpack(const std::uint8_t* bytes, Endian endian) {
  using Bits = typename detail::PackedBits<T>::type;
  using Wide = detail::ShiftBits<Bits>;
  Wide wide{0};
  for (std::size_t significance = 0; significance < sizeof(Bits); ++significance) {
    const auto byte = static_cast<Wide>(bytes[detail::byte_position(significance, sizeof(Bits), endian)]);
    wide |= static_cast<Wide>(byte << (8U * significance));
  }
  const auto bits = static_cast<Bits>(wide);
  if constexpr (std::is_same_v<T, bool>) {
    return bits != 0;
  } else if constexpr (Floating<T>) {
    return std::bit_cast<T>(bits);
  } else {
    return static_cast<T>(bits);  // modular since C++20: the bits read as two's complement
  }
}

}  // namespace duet::blocks
