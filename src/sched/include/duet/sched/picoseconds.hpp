#pragma once
// The response-time analysis counts time in whole picoseconds, as 64-bit integers: its fixed-point iterations are then
// exact, so a busy period that ends exactly when the next releases come (utilization exactly 1) is found to end,
// where floating-point sums could miss it by a rounding. Task files give microseconds with up to six decimals.

#include <cstdint>

#include "duet/support/result.hpp"

namespace duet::sched {

using Picoseconds = std::int64_t;

// The longest time the analysis takes as input: 2^61 ps (about 26.7 days), so that a C plus both overheads still fits
// in 64 bits.
inline constexpr Picoseconds longest_time = Picoseconds{1} << 61;

// `microseconds` as whole picoseconds; an error (without the field's name: the caller adds it) if it is negative,
// finer than a picosecond or longer than `longest_time`.
[[nodiscard]] Result<Picoseconds> whole_picoseconds(double microseconds);

[[nodiscard]] double to_microseconds(Picoseconds time);

}  // namespace duet::sched
