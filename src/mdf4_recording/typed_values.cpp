#include "duet/mdf4_recording/typed_values.hpp"

#include <cmath>
#include <limits>

#include "duet/model/data_type.hpp"

namespace duet::mdf4_recording {
namespace {

template <typename Integer>
Result<mdf4::Value> integer(double value, std::string_view type) {
  // The range test is on doubles: both ends of every integer up to 32 bits are exact, and for 64 bits the upper end
  // rounds up to 2^63 or 2^64, which the strict comparison excludes.
  if (std::trunc(value) != value || value < static_cast<double>(std::numeric_limits<Integer>::min()) ||
      !(value < static_cast<double>(std::numeric_limits<Integer>::max()) + 1.0)) {
    return Failure{model::format_number(value) + " is no " + std::string{type} + " value"};
  }
  return mdf4::Value{static_cast<Integer>(value)};
}

}  // namespace

mdf4::ValueType value_type(model::DataType type) {
  switch (type) {
    case model::DataType::float64: return mdf4::ValueType::f64;
    case model::DataType::float32: return mdf4::ValueType::f32;
    case model::DataType::int8: return mdf4::ValueType::i8;
    case model::DataType::int16: return mdf4::ValueType::i16;
    case model::DataType::int32: return mdf4::ValueType::i32;
    case model::DataType::uint8: return mdf4::ValueType::u8;
    case model::DataType::uint16: return mdf4::ValueType::u16;
    case model::DataType::uint32: return mdf4::ValueType::u32;
    case model::DataType::boolean: return mdf4::ValueType::boolean;
  }
  return mdf4::ValueType::f64;
}

Result<mdf4::Value> typed_value(double value, mdf4::ValueType type) {
  switch (type) {
    case mdf4::ValueType::boolean:
      if (value != 0 && value != 1) return Failure{model::format_number(value) + " is no boolean value"};
      return mdf4::Value{value == 1};
    case mdf4::ValueType::u8: return integer<std::uint8_t>(value, "u8");
    case mdf4::ValueType::u16: return integer<std::uint16_t>(value, "u16");
    case mdf4::ValueType::u32: return integer<std::uint32_t>(value, "u32");
    case mdf4::ValueType::u64: return integer<std::uint64_t>(value, "u64");
    case mdf4::ValueType::i8: return integer<std::int8_t>(value, "i8");
    case mdf4::ValueType::i16: return integer<std::int16_t>(value, "i16");
    case mdf4::ValueType::i32: return integer<std::int32_t>(value, "i32");
    case mdf4::ValueType::i64: return integer<std::int64_t>(value, "i64");
    case mdf4::ValueType::f32:
      if (std::isfinite(value) && std::abs(value) > std::numeric_limits<float>::max())
        return Failure{model::format_number(value) + " is no f32 value"};
      return mdf4::Value{static_cast<float>(value)};
    case mdf4::ValueType::f64: return mdf4::Value{value};
  }
  return Failure{"no such type"};
}

}  // namespace duet::mdf4_recording
