#pragma once
// The data types of signals and parameters, as the model file names them, as C++ names them, and what values they
// hold. Simulation, generation and the A2L all take their names from here.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "duet/model/model.hpp"

namespace duet::model {

[[nodiscard]] std::string_view type_name(DataType type);  // as in model files: double, single, int8, ...
[[nodiscard]] std::optional<DataType> parse_type_name(std::string_view name);  // the reverse; none for another word
[[nodiscard]] std::string_view cpp_type(DataType type);                        // double, float, std::int8_t, ..., bool
[[nodiscard]] std::size_t size_of(DataType type);                              // bytes
[[nodiscard]] bool is_floating(DataType type);
[[nodiscard]] bool is_integer(DataType type);

// Whether the type holds `value` exactly (a float holds any finite double within its range, rounded).
[[nodiscard]] bool fits(double value, DataType type);

}  // namespace duet::model
