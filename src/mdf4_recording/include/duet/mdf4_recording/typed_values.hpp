#pragma once
// Model signals as MDF 4 values: the stored type of a model data type, and a value the simulation holds as a double
// back in its signal's exact type (a bool, an int16, a float), so that the file keeps what the model computed.

#include "duet/mdf4/spec.hpp"
#include "duet/mdf4/writer.hpp"
#include "duet/model/model.hpp"
#include "duet/support/result.hpp"

namespace duet::mdf4_recording {

// double f64, single f32, int8 i8, ..., uint32 u32, boolean boolean (stored as an unsigned byte 0 or 1).
[[nodiscard]] mdf4::ValueType value_type(model::DataType type);

// `value` as a value of `type`: refused (naming the value and the type) when the type does not hold it exactly,
// a float excepted, which takes any finite double in its range rounded, and NaN and infinities.
[[nodiscard]] Result<mdf4::Value> typed_value(double value, mdf4::ValueType type);

}  // namespace duet::mdf4_recording
