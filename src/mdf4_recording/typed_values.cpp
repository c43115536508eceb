#include "duet/mdf4_recording/typed_values.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>

#include "duet/mdf4/exact_value.hpp"
#include "duet/model/data_type.hpp"
#include "duet/support/number_text.hpp"

namespace duet::mdf4_recording {
namespace {

// In ValueType's order.
constexpr std::array<std::string_view, 11> stored_names{"boolean", "u8",  "u16", "u32", "u64", "i8",
                                                        "i16",     "i32", "i64", "f32", "f64"};

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
  if (type == mdf4::ValueType::f32) {  // rounded, as a float signal's arithmetic rounds
    if (std::isfinite(value) && std::abs(value) > std::numeric_limits<float>::max())
      return Failure{shortest_text(value) + " is no f32 value"};
    return mdf4::Value{static_cast<float>(value)};
  }
  std::optional<mdf4::Value> exact = mdf4::exactly(type, value);
  if (!exact)
    return Failure{shortest_text(value) + " is no " + std::string{stored_names[static_cast<std::size_t>(type)]} +
                   " value"};
  return *exact;
}

}  // namespace duet::mdf4_recording
