#pragma once
// For the model's passes (private to src/model): calls a generic function with a value of the C++ type that stands
// for a data type, so that one template serves every element type.

#include <cstdint>

#include "duet/model/model.hpp"

namespace duet::model {

template <typename Function>
decltype(auto) with_type(DataType type, Function&& function) {
  switch (type) {
    case DataType::float64: return function(double{});
    case DataType::float32: return function(float{});
    case DataType::int8: return function(std::int8_t{});
    case DataType::int16: return function(std::int16_t{});
    case DataType::int32: return function(std::int32_t{});
    case DataType::uint8: return function(std::uint8_t{});
    case DataType::uint16: return function(std::uint16_t{});
    case DataType::uint32: return function(std::uint32_t{});
    case DataType::boolean: return function(bool{});
  }
  return function(double{});  // not a DataType: unreachable
}

}  // namespace duet::model
