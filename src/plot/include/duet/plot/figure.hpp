#pragma once
// A figure of sampled signals and its picture as SVG, for `duet sim` and for plotting a recorded CSV again.

#include <string>
#include <vector>

namespace duet::plot {

// One signal: a value per time sample of its Figure. NaN or an infinite value is a missing sample (a gap in the line).
struct Series {
  std::string name;
  std::string unit;  // series with the same unit share a panel and its y axis; "" is a unit of its own
  std::vector<double> values;
};

struct Figure {
  std::string title;
  std::string time_unit = "s";
  std::vector<double> time;  // increasing; a series with fewer or more values than this is drawn as far as both go
  std::vector<Series> series;
};

// The figure as a self-contained SVG 1.1 document (no scripts, fonts or style sheets from outside), 900 px wide:
// - one panel per distinct unit in order of first appearance, stacked, about 220 px each, with its own y axis, a
//   legend, and a shared time axis under the last one;
// - ticks at 1, 2 or 5 x 10^n, labelled with the digits their step needs; a panel whose series hold only 0 and 1
//   gets the ticks 0 and 1;
// - every sample is held until the next one and then jumps (these are discrete-time signals), so lines are steps;
// - a missing sample (NaN, infinite value or time) ends a line and the next finite one starts a new one;
// - where many samples fall into one pixel column, only the first, the smallest, the largest and the last of them
//   are drawn (in their order), so the picture stays a few hundred kB for millions of samples and a one-sample
//   spike still shows;
// - names, units and the title are escaped, and bytes that are not UTF-8 are replaced, so any text is safe.
// An empty figure, or one without samples, gives a small document that says "no data".
[[nodiscard]] std::string to_svg(const Figure& figure);

}  // namespace duet::plot
