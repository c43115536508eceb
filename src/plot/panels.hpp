#pragma once
// Which series share a panel, and the ranges the panels' axes must cover.

#include <cstddef>
#include <string>
#include <vector>

#include "duet/plot/figure.hpp"
#include "ticks.hpp"

namespace duet::plot {

struct Panel {
  std::string unit;
  std::vector<std::size_t> series;  // indices into Figure::series, in the figure's order
  bool binary = false;              // every series holds only 0 and 1: the axis shows just those
};

// One panel per distinct unit, in the order the units first appear.
[[nodiscard]] std::vector<Panel> panels_by_unit(const Figure& figure);

// How many samples of `series` are drawn: as many as it and the time both have.
[[nodiscard]] std::size_t sample_count(const Figure& figure, const Series& series);

// Whether any series has a sample to draw (finite or not).
[[nodiscard]] bool has_samples(const Figure& figure);

// The finite times, made a usable range.
[[nodiscard]] Range time_range(const Figure& figure);

// The panel's finite values (of samples at a finite time), padded; 0 and 1 padded alike for a binary panel.
[[nodiscard]] Range value_range(const Figure& figure, const Panel& panel);

}  // namespace duet::plot
