#include "duet/mdf4/exact_value.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace duet::mdf4 {
namespace {

template <typename Integer>
std::optional<Value> integer(double value) {
  // The range test is on doubles: both ends of every integer up to 32 bits are exact, and for 64 bits max() + 1
  // rounds to 2^63 or 2^64, the first value past the type, which the strict comparison excludes.
  if (std::trunc(value) != value || value < static_cast<double>(std::numeric_limits<Integer>::min()) ||
      !(value < static_cast<double>(std::numeric_limits<Integer>::max()) + 1.0)) {
    return std::nullopt;
  }
  return Value{static_cast<Integer>(value)};
}

}  // namespace

std::optional<Value> exactly(ValueType type, double value) {
  switch (type) {
    case ValueType::boolean:
      if (value != 0 && value != 1) return std::nullopt;
      return Value{value == 1};
    case ValueType::u8: return integer<std::uint8_t>(value);
    case ValueType::u16: return integer<std::uint16_t>(value);
    case ValueType::u32: return integer<std::uint32_t>(value);
    case ValueType::u64: return integer<std::uint64_t>(value);
    case ValueType::i8: return integer<std::int8_t>(value);
    case ValueType::i16: return integer<std::int16_t>(value);
    case ValueType::i32: return integer<std::int32_t>(value);
    case ValueType::i64: return integer<std::int64_t>(value);
    case ValueType::f32: {
      if (std::isfinite(value) && (std::fabs(value) > std::numeric_limits<float>::max() ||
                                   static_cast<double>(static_cast<float>(value)) != value)) {
        return std::nullopt;
      }
      return Value{static_cast<float>(value)};
    }
    case ValueType::f64: break;
  }
  return Value{value};
}

}  // namespace duet::mdf4
