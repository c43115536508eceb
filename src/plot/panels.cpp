#include "panels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace duet::plot {
namespace {

struct Extremes {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  void add(double value) {
    min = std::min(min, value);
    max = std::max(max, value);
  }
  [[nodiscard]] bool empty() const { return min > max; }
};

bool holds_only_zero_and_one(const Figure& figure, const Series& series) {
  bool any = false;
  for (std::size_t i = 0; i < sample_count(figure, series); ++i) {
    const double value = series.values[i];
    if (!std::isfinite(value)) continue;
    if (value != 0 && value != 1) return false;
    any = true;
  }
  return any;
}

}  // namespace

std::vector<Panel> panels_by_unit(const Figure& figure) {
  std::vector<Panel> panels;
  for (std::size_t i = 0; i < figure.series.size(); ++i) {
    const std::string& unit = figure.series[i].unit;
    auto panel = std::find_if(panels.begin(), panels.end(), [&](const Panel& p) { return p.unit == unit; });
    if (panel == panels.end()) panel = panels.insert(panels.end(), Panel{.unit = unit, .series = {}, .binary = true});
    panel->series.push_back(i);
    panel->binary = panel->binary && holds_only_zero_and_one(figure, figure.series[i]);
  }
  return panels;
}

std::size_t sample_count(const Figure& figure, const Series& series) {
  return std::min(figure.time.size(), series.values.size());
}

bool has_samples(const Figure& figure) {
  return std::any_of(figure.series.begin(), figure.series.end(),
                     [&](const Series& series) { return sample_count(figure, series) > 0; });
}

Range time_range(const Figure& figure) {
  Extremes extremes;
  for (const double time : figure.time) {
    if (std::isfinite(time)) extremes.add(time);
  }
  return extremes.empty() ? Range{0, 1} : usable_range(extremes.min, extremes.max);
}

Range value_range(const Figure& figure, const Panel& panel) {
  if (panel.binary) return padded_range(0, 1);
  Extremes extremes;
  for (const std::size_t index : panel.series) {
    const Series& series = figure.series[index];
    for (std::size_t i = 0; i < sample_count(figure, series); ++i) {
      if (std::isfinite(series.values[i]) && std::isfinite(figure.time[i])) extremes.add(series.values[i]);
    }
  }
  return extremes.empty() ? padded_range(0, 0) : padded_range(extremes.min, extremes.max);
}

}  // namespace duet::plot
