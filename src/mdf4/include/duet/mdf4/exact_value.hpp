#pragma once
// A double as a value of a channel's type, when it is exactly one: what a recorder that holds its values as doubles
// needs to store each in its own type without changing it.

#include <optional>

#include "duet/mdf4/spec.hpp"
#include "duet/mdf4/writer.hpp"

namespace duet::mdf4 {

// `value` as a `type`: a whole number within an integer type's range, 0 or 1 for a boolean, for f32 a number a float
// holds exactly (infinities and NaN included), any double for f64. Nothing when it is not exactly one.
[[nodiscard]] std::optional<Value> exactly(ValueType type, double value);

}  // namespace duet::mdf4
