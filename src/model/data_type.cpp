#include "duet/model/data_type.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace duet::model {
namespace {

struct TypeFacts {
  std::string_view name;
  std::string_view cpp;
  std::size_t size;
  double lowest;
  double highest;
};

TypeFacts facts(DataType type) {
  constexpr double float_max = std::numeric_limits<float>::max();
  constexpr double double_max = std::numeric_limits<double>::max();
  switch (type) {
    case DataType::float64: return {"double", "double", 8, -double_max, double_max};
    case DataType::float32: return {"single", "float", 4, -float_max, float_max};
    case DataType::int8: return {"int8", "std::int8_t", 1, INT8_MIN, INT8_MAX};
    case DataType::int16: return {"int16", "std::int16_t", 2, INT16_MIN, INT16_MAX};
    case DataType::int32: return {"int32", "std::int32_t", 4, INT32_MIN, INT32_MAX};
    case DataType::uint8: return {"uint8", "std::uint8_t", 1, 0, UINT8_MAX};
    case DataType::uint16: return {"uint16", "std::uint16_t", 2, 0, UINT16_MAX};
    case DataType::uint32: return {"uint32", "std::uint32_t", 4, 0, UINT32_MAX};
    case DataType::boolean: return {"boolean", "bool", 1, 0, 1};
  }
  return {"?", "?", 0, 0, 0};
}

}  // namespace

std::string_view type_name(DataType type) { return facts(type).name; }

std::optional<DataType> parse_type_name(std::string_view name) {
  for (const DataType type : {DataType::float64, DataType::float32, DataType::int8, DataType::int16, DataType::int32,
                              DataType::uint8, DataType::uint16, DataType::uint32, DataType::boolean}) {
    if (facts(type).name == name) return type;
  }
  return std::nullopt;
}
std::string_view cpp_type(DataType type) { return facts(type).cpp; }
std::size_t size_of(DataType type) { return facts(type).size; }
bool is_floating(DataType type) { return type == DataType::float64 || type == DataType::float32; }
bool is_integer(DataType type) { return !is_floating(type) && type != DataType::boolean; }

bool fits(double value, DataType type) {
  const TypeFacts range = facts(type);
  if (!std::isfinite(value) || value < range.lowest || value > range.highest) return false;
  return is_floating(type) || value == std::trunc(value);
}

}  // namespace duet::model
