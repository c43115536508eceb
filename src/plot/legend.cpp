#include "legend.hpp"

#include <algorithm>
#include <string_view>

namespace duet::plot {
namespace {

constexpr double character_width = 6.6;  // an average for 12 px sans-serif; an estimate is all SVG allows
constexpr double swatch_width = 24;      // the line sample and the space after it
constexpr double entry_gap = 18;
constexpr std::size_t longest_name = 48;

bool continues_character(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Characters, not bytes: UTF-8 continuation bytes do not count.
std::size_t characters(std::string_view text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return !continues_character(c); }));
}

std::string shortened(std::string_view name) {
  if (characters(name) <= longest_name) return std::string{name};
  std::size_t kept = 0;
  std::size_t end = 0;
  while (end < name.size() && (kept < longest_name - 1 || continues_character(name[end]))) {
    if (!continues_character(name[end])) ++kept;
    ++end;
  }
  return std::string{name.substr(0, end)} + "\u2026";
}

}  // namespace

std::vector<LegendEntry> legend_layout(const Figure& figure, const Panel& panel, double width) {
  std::vector<LegendEntry> entries;
  double x = 0;
  std::size_t line = 0;
  for (const std::size_t index : panel.series) {
    std::string name = shortened(figure.series[index].name);
    const double entry_width = swatch_width + character_width * static_cast<double>(characters(name)) + entry_gap;
    if (x > 0 && x + entry_width > width) {
      x = 0;
      ++line;
    }
    entries.push_back({.series = index, .name = std::move(name), .x = x, .line = line});
    x += entry_width;
  }
  return entries;
}

double legend_height(const std::vector<LegendEntry>& entries, double line_height) {
  return entries.empty() ? 0 : line_height * static_cast<double>(entries.back().line + 1);
}

}  // namespace duet::plot
