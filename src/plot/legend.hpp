#pragma once
// Where a panel's legend entries go: left to right above the plot, wrapping to a new line at its width.

#include <cstddef>
#include <string>
#include <vector>

#include "duet/plot/figure.hpp"
#include "panels.hpp"

namespace duet::plot {

struct LegendEntry {
  std::size_t series = 0;
  std::string name;  // cut to 48 characters with an ellipsis, so one long name cannot push the others off the page
  double x = 0;      // from the plot's left edge
  std::size_t line = 0;
};

// The entries of `panel`, laid out for a plot `width` pixels wide (12 px sans-serif, whose widths are guessed).
[[nodiscard]] std::vector<LegendEntry> legend_layout(const Figure& figure, const Panel& panel, double width);

// The height the entries take, `line_height` per line.
[[nodiscard]] double legend_height(const std::vector<LegendEntry>& entries, double line_height);

}  // namespace duet::plot
