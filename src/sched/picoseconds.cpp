#include "duet/sched/picoseconds.hpp"

#include <cmath>

namespace duet::sched {
namespace {

constexpr double picoseconds_per_microsecond = 1e6;

}  // namespace

Result<Picoseconds> whole_picoseconds(double microseconds) {
  if (std::isnan(microseconds)) return Failure{"is not a number"};
  if (microseconds < 0) return Failure{"is negative; times are never negative"};
  const double scaled = microseconds * picoseconds_per_microsecond;
  if (scaled > static_cast<double>(longest_time)) {
    return Failure{"is longer than 2^61 ps (about 26.7 days), the longest time the analysis counts"};
  }
  const double nearest = std::round(scaled);
  // A decimal with at most six places lands within a few units in the last place of a whole number once scaled
  // (parsing and scaling each round once); a seventh decimal lands much farther off.
  if (std::abs(scaled - nearest) > std::ldexp(scaled, -48)) {
    return Failure{"is finer than a picosecond, the unit the analysis counts in (at most six decimals in us)"};
  }
  return static_cast<Picoseconds>(nearest);
}

double to_microseconds(Picoseconds time) { return static_cast<double>(time) / picoseconds_per_microsecond; }

}  // namespace duet::sched
