#pragma once
// Axis ranges and ticks that read well: steps of 1, 2 or 5 x 10^n, labelled with exactly the digits the step needs,
// so that 0.1 + 0.2 never shows up as 0.30000000000000004.

#include <cstddef>
#include <string>
#include <vector>

namespace duet::plot {

struct Range {
  double low = 0;
  double high = 1;
};

// The y range for data between `min` and `max` (finite, min <= max): a 5 % margin either side, so lines do not run
// along the frame. A (nearly) constant value gets +-10 % of itself, or +-1 at zero, instead of an empty range.
[[nodiscard]] Range padded_range(double min, double max);

// [min, max] as it is (a time axis starts at its first sample), unless it is (nearly) a single value, which is
// widened like padded_range.
[[nodiscard]] Range usable_range(double min, double max);

struct Tick {
  double value = 0;
  std::string label;
};

struct Ticks {
  double step = 1;
  std::vector<Tick> ticks;  // every multiple of step within the range, increasing
};

// The finest step of 1, 2 or 5 x 10^n that puts at most `most` ticks into `range`.
// Precondition: range is a usable_range or padded_range result, most >= 2.
[[nodiscard]] Ticks choose_ticks(Range range, std::size_t most);

// multiple x 10^exponent, written exactly: fixed point with -exponent decimals ("0.25", "1500") while the exponent is
// moderate, else scientific with a trimmed mantissa ("1.5e-6", "2e9").
[[nodiscard]] std::string decimal_label(long long multiple, int exponent);

}  // namespace duet::plot
