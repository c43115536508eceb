#include "trace.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace duet::plot {
namespace {

// Appends the samples [first, last) of one pixel column: all of them when there are few, else the four that
// shape the column (first, the extremes in the order they occur, last).
void add_column(Trace& line, std::span<const double> values, std::span<const double> xs, std::size_t first,
                std::size_t last) {
  if (last - first <= 4) {
    for (std::size_t i = first; i < last; ++i) line.points.push_back({xs[i], values[i]});
    return;
  }
  std::size_t lowest = first;
  std::size_t highest = first;
  for (std::size_t i = first + 1; i < last; ++i) {
    if (values[i] < values[lowest]) lowest = i;
    if (values[i] > values[highest]) highest = i;
  }
  std::size_t kept[4] = {first, std::min(lowest, highest), std::max(lowest, highest), last - 1};
  for (std::size_t k = 0; k < 4; ++k) {
    if (k > 0 && kept[k] == kept[k - 1]) continue;
    line.points.push_back({xs[kept[k]], values[kept[k]]});
  }
}

}  // namespace

double TimeScale::operator()(double time) const {
  const double x = (time - time_low) / (time_high - time_low) * width;
  return std::clamp(x, 0.0, width);
}

std::vector<Trace> trace(std::span<const double> time, std::span<const double> values, const TimeScale& scale) {
  const std::size_t count = std::min(time.size(), values.size());
  std::vector<double> xs(count);
  for (std::size_t i = 0; i < count; ++i)
    xs[i] = std::isfinite(time[i]) ? scale(time[i]) : std::numeric_limits<double>::quiet_NaN();
  const auto present = [&](std::size_t i) { return std::isfinite(values[i]) && std::isfinite(xs[i]); };

  std::vector<Trace> lines;
  std::size_t i = 0;
  while (i < count) {
    if (!present(i)) {
      ++i;
      continue;
    }
    Trace& line = lines.emplace_back();
    while (i < count && present(i)) {
      const auto column = static_cast<long long>(std::floor(xs[i]));
      std::size_t end = i + 1;
      while (end < count && present(end) && static_cast<long long>(std::floor(xs[end])) == column) ++end;
      add_column(line, values, xs, i, end);
      i = end;
    }
    if (i < count && std::isfinite(xs[i])) line.end_x = xs[i];
  }
  return lines;
}

}  // namespace duet::plot
