#pragma once
// A2L MEASUREMENTs as MDF 4 channels: the exact stored type, the name, unit and long identifier, the linear
// conversion, and the raw values of a DAQ sample in their types, so that a reader's physical value is the one
// duet's master computes (xcp::host::decode) and `duet xcp record` prints in its CSV.

#include <cstdint>
#include <span>
#include <vector>

#include "duet/mdf4/spec.hpp"
#include "duet/mdf4/writer.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::mdf4_recording {

// The MDF type that holds an A2L data type exactly: UBYTE u8, SBYTE i8, ..., A_UINT64 u64, FLOAT32_IEEE f32, ...
[[nodiscard]] mdf4::ValueType value_type(xcp::host::DataType type);

// The variable's channel (a vector of its elements for an array). A linear conversion (LINEAR, a linear RAT_FUNC) is
// written as one, IDENTICAL as none. The others are stored raw without a conversion, and the comment says so: a
// verbal table with its names, a conversion the A2L reader does not apply by its type.
[[nodiscard]] mdf4::ChannelSpec channel(const xcp::host::Variable& variable);

// Appends the raw values of the variable's elements in `bytes` (the slave's little-endian order, size_of(type) each)
// to `values`, each in its exact type.
void append_raw_values(const xcp::host::Variable& variable, std::span<const std::uint8_t> bytes,
                       std::vector<mdf4::Value>& values);

}  // namespace duet::mdf4_recording
