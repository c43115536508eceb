#pragma once
// How a sampled signal becomes lines: runs of finite samples, each sample held until the next, with the samples of
// one pixel column reduced to the few that shape the picture.

#include <optional>
#include <span>
#include <vector>

namespace duet::plot {

// Time to pixels from the plot's left edge, clamped to [0, width].
struct TimeScale {
  double time_low = 0;
  double time_high = 1;
  double width = 1;
  [[nodiscard]] double operator()(double time) const;
};

struct TracePoint {
  double x = 0;      // pixels from the plot's left edge
  double value = 0;  // in the series' unit
};

// One unbroken line. Each point's value holds until the next point's x; the last one holds until end_x, the time
// of the missing sample that ends the line (none after the last sample).
struct Trace {
  std::vector<TracePoint> points;
  std::optional<double> end_x;
};

// The lines of one series (values[i] sampled at time[i], as many samples as both have). A sample whose value or time
// is NaN or infinite ends a line. Within a run of consecutive samples in the same pixel column, runs of more than
// four keep only their first, smallest, largest and last samples, in sample order: the drawn line is the same to the
// pixel, spikes of a single sample survive, and a series yields at most four points per column and line.
[[nodiscard]] std::vector<Trace> trace(std::span<const double> time, std::span<const double> values,
                                       const TimeScale& scale);

}  // namespace duet::plot
