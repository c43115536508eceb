#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "duet/plot/figure.hpp"
#include "legend.hpp"
#include "panels.hpp"
#include "ticks.hpp"
#include "trace.hpp"
#include "xml.hpp"

namespace duet::plot {
namespace {

// The page, in pixels. A panel is its legend lines, the plot and a gap: about 220 px with one legend line.
constexpr double page_width = 900;
constexpr double plot_left = 78;  // room for tick labels such as "-1.25e-6" and the rotated unit
constexpr double plot_width = page_width - plot_left - 24;
constexpr double plot_height = 170;
constexpr double legend_line = 18;
constexpr double panel_gap = 30;
constexpr double time_axis_height = 50;
constexpr std::size_t most_value_ticks = 6;  // about 28 px apart: labels never touch
constexpr std::size_t most_time_ticks = 10;  // about 80 px apart: room for "0.00125"
constexpr std::string_view grid = "stroke=\"#e3e3e3\"";
constexpr std::string_view frame = "stroke=\"#888\"";

// Eight colours that tell apart on white; after eight, the colours come again with dashes.
struct Style {
  std::string_view colour;
  std::string_view dashes;
};

Style style_of(std::size_t series) {
  constexpr std::array<std::string_view, 8> colours{"#1f5fbf", "#e8590c", "#2f9e44", "#c92a2a",
                                                    "#7b2cbf", "#0b7285", "#8d5524", "#d6336c"};
  constexpr std::array<std::string_view, 3> dashes{"", "7 3", "2 2"};
  return {colours[series % colours.size()], dashes[(series / colours.size()) % dashes.size()]};
}

std::string stroke(Style style) {
  std::string attributes = "stroke=\"" + std::string{style.colour} + "\"";
  if (!style.dashes.empty()) attributes += " stroke-dasharray=\"" + std::string{style.dashes} + "\"";
  return attributes;
}

// A step line in page coordinates: each value held until the next point, then a jump. Vertices on a straight
// horizontal or vertical stretch between their neighbours are dropped, so a constant stretch is one segment.
class StepLine {
 public:
  void add(double x, double y) {
    const std::pair<double, double> vertex{std::round(x * 10) / 10, std::round(y * 10) / 10};
    if (!vertices_.empty() && vertices_.back() == vertex) return;
    if (vertices_.size() >= 2) {
      const auto [ax, ay] = vertices_[vertices_.size() - 2];
      const auto [bx, by] = vertices_.back();
      const auto between = [](double a, double b, double c) { return (a <= b && b <= c) || (a >= b && b >= c); };
      if ((ay == by && by == vertex.second && between(ax, bx, vertex.first)) ||
          (ax == bx && bx == vertex.first && between(ay, by, vertex.second))) {
        vertices_.back() = vertex;
        return;
      }
    }
    vertices_.push_back(vertex);
  }

  void write(std::string& svg, Style style) const {
    svg += "<polyline " + stroke(style) + " points=\"";
    // A lone vertex is written twice: a line of no length, which the round caps draw as a dot.
    for (std::size_t i = 0; i < std::max<std::size_t>(vertices_.size(), 2); ++i) {
      const auto [x, y] = vertices_[std::min(i, vertices_.size() - 1)];
      if (i > 0) svg += ' ';
      append_coordinate(svg, x);
      svg += ',';
      append_coordinate(svg, y);
    }
    svg += "\"/>\n";
  }

 private:
  std::vector<std::pair<double, double>> vertices_;
};

void begin_document(std::string& svg, double height, const std::string& title) {
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"";
  append_attribute(svg, "width", page_width);
  append_attribute(svg, "height", height);
  svg += " viewBox=\"0 0 ";
  append_coordinate(svg, page_width);
  svg += ' ';
  append_coordinate(svg, height);
  svg += "\" font-family=\"sans-serif\" font-size=\"12\" fill=\"#222\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  if (!title.empty()) append_text(svg, plot_left, 26, R"(font-size="15" font-weight="bold")", title);
}

void append_rect(std::string& svg, double x, double y, double width, double height, std::string_view attributes) {
  svg += "<rect";
  append_attribute(svg, "x", x);
  append_attribute(svg, "y", y);
  append_attribute(svg, "width", width);
  append_attribute(svg, "height", height);
  if (!attributes.empty()) svg += ' ';
  svg += attributes;
  svg += "/>";
}

class FigureWriter {
 public:
  explicit FigureWriter(const Figure& figure)
      : figure_(figure),
        time_(time_range(figure)),
        time_ticks_(choose_ticks(time_, most_time_ticks)),
        scale_{.time_low = time_.low, .time_high = time_.high, .width = plot_width} {}

  std::string write() {
    const std::vector<Panel> panels = panels_by_unit(figure_);
    std::vector<std::vector<LegendEntry>> legends;
    double height = top() + time_axis_height - panel_gap;
    for (const Panel& panel : panels) {
      legends.push_back(legend_layout(figure_, panel, plot_width));
      height += legend_height(legends.back(), legend_line) + plot_height + panel_gap;
    }
    begin_document(svg_, height, figure_.title);
    double y = top();
    for (std::size_t i = 0; i < panels.size(); ++i) {
      y += legend_height(legends[i], legend_line);
      svg_ += "<g class=\"panel\">\n";
      write_legend(legends[i], y);
      write_panel(panels[i], y, i);
      svg_ += "</g>\n";
      y += plot_height + panel_gap;
    }
    write_time_axis(y - panel_gap);
    svg_ += "</svg>\n";
    return std::move(svg_);
  }

 private:
  [[nodiscard]] double top() const { return figure_.title.empty() ? 16 : 44; }

  void write_legend(const std::vector<LegendEntry>& legend, double plot_top) {
    const double first_line = plot_top - legend_height(legend, legend_line) + 12;
    for (const LegendEntry& entry : legend) {
      const double y = first_line + legend_line * static_cast<double>(entry.line);
      const double x = plot_left + entry.x;
      append_line(svg_, x, y - 4, x + 18, y - 4, stroke(style_of(entry.series)) + " stroke-width=\"2.5\"");
      append_text(svg_, x + 24, y, "", entry.name);
    }
  }

  void write_panel(const Panel& panel, double plot_top, std::size_t number) {
    const Range values = value_range(figure_, panel);
    const auto page_y = [&](double value) {
      return plot_top + (values.high - value) / (values.high - values.low) * plot_height;
    };
    for (const Tick& tick : choose_ticks(values, panel.binary ? 2 : most_value_ticks).ticks) {
      append_line(svg_, plot_left, page_y(tick.value), plot_left + plot_width, page_y(tick.value), grid);
      append_text(svg_, plot_left - 6, page_y(tick.value) + 4, "text-anchor=\"end\"", tick.label);
    }
    for (const Tick& tick : time_ticks_.ticks) {
      const double x = plot_left + scale_(tick.value);
      append_line(svg_, x, plot_top, x, plot_top + plot_height, grid);
    }
    if (!panel.unit.empty()) {
      const double middle = std::round(plot_top + plot_height / 2);
      const std::string turned =
          R"(text-anchor="middle" transform="rotate(-90 18 )" + std::to_string(static_cast<int>(middle)) + R"x()")x";
      append_text(svg_, 18, middle, turned, panel.unit);
    }
    // Lines stay inside the plot even where rounding would take them a hair outside.
    const std::string clip = "duet-plot-" + std::to_string(number);
    svg_ += "<clipPath id=\"" + clip + "\">";
    append_rect(svg_, plot_left, plot_top, plot_width, plot_height, "");
    svg_ += "</clipPath>\n<g clip-path=\"url(#" + clip +
            ")\" fill=\"none\" stroke-width=\"1.5\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
    for (const std::size_t index : panel.series) write_series(index, page_y);
    svg_ += "</g>\n";
    append_rect(svg_, plot_left, plot_top, plot_width, plot_height, std::string{"fill=\"none\" "} + std::string{frame});
    svg_ += '\n';
  }

  template <typename PageY>
  void write_series(std::size_t index, const PageY& page_y) {
    const Series& series = figure_.series[index];
    const std::size_t count = sample_count(figure_, series);
    for (const Trace& line : trace({figure_.time.data(), count}, {series.values.data(), count}, scale_)) {
      StepLine step;
      for (std::size_t i = 0; i < line.points.size(); ++i) {
        const double x = plot_left + line.points[i].x;
        if (i > 0) step.add(x, page_y(line.points[i - 1].value));
        step.add(x, page_y(line.points[i].value));
      }
      if (line.end_x) step.add(plot_left + *line.end_x, page_y(line.points.back().value));
      step.write(svg_, style_of(index));
    }
  }

  void write_time_axis(double plot_bottom) {
    for (const Tick& tick : time_ticks_.ticks) {
      const double x = plot_left + scale_(tick.value);
      append_line(svg_, x, plot_bottom, x, plot_bottom + 5, frame);
      append_text(svg_, x, plot_bottom + 18, "text-anchor=\"middle\"", tick.label);
    }
    const std::string label = figure_.time_unit.empty() ? "time" : "time [" + figure_.time_unit + "]";
    append_text(svg_, plot_left + plot_width / 2, plot_bottom + 38, "text-anchor=\"middle\"", label);
  }

  const Figure& figure_;
  Range time_;
  Ticks time_ticks_;
  TimeScale scale_;
  std::string svg_;
};

std::string no_data(const Figure& figure) {
  std::string svg;
  begin_document(svg, 160, figure.title);
  append_rect(svg, plot_left, 44, plot_width, 96, std::string{"fill=\"none\" "} + std::string{frame});
  svg += '\n';
  append_text(svg, plot_left + plot_width / 2, 97, R"(text-anchor="middle" fill="#888" font-size="15")", "no data");
  return svg + "</svg>\n";
}

}  // namespace

std::string to_svg(const Figure& figure) {
  return has_samples(figure) ? FigureWriter{figure}.write() : no_data(figure);
}

}  // namespace duet::plot
