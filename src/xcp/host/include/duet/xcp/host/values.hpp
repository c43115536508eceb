#pragma once
// Values of A2L variables: raw bytes in the slave's (little-endian) order <-> physical numbers, through the variable's
// data type and conversion.

#include <cstdint>
#include <span>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::xcp::host {

// The physical values of a variable's `count` elements in `bytes` (size_of(type) * count bytes).
std::vector<double> decode(const Variable& variable, std::span<const std::uint8_t> bytes);

// The bytes of one element with physical value `value`: refused if it lies outside the variable's limits or its type.
Result<std::vector<std::uint8_t>> encode(const Variable& variable, double value);

}  // namespace duet::xcp::host
