#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

#include "duet/plot/figure.hpp"
#include "panels.hpp"
#include "well_formed.hpp"

namespace duet::plot {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::size_t occurrences(std::string_view text, std::string_view part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string_view::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

Figure robot() {
  Figure figure{.title = "Balancing robot", .time = {0, 0.01, 0.02, 0.03, 0.04}, .series = {}};
  figure.series.push_back({.name = "pitch", .unit = "rad", .values = {0.1, 0.05, 0.0, -0.02, -0.01}});
  figure.series.push_back({.name = "motor", .unit = "V", .values = {0, 3.5, 6, 2, 1}});
  figure.series.push_back({.name = "pitch reference", .unit = "rad", .values = {0, 0, 0, 0, 0}});
  figure.series.push_back({.name = "saturated", .unit = "", .values = {0, 1, 1, 0, 0}});
  return figure;
}

TEST(PlotPanels, OnePanelPerUnitInOrderOfAppearance) {
  const std::vector<Panel> panels = panels_by_unit(robot());
  ASSERT_EQ(panels.size(), 3U);
  EXPECT_EQ(panels[0].unit, "rad");
  EXPECT_EQ(panels[0].series, (std::vector<std::size_t>{0, 2}));
  EXPECT_FALSE(panels[0].binary);
  EXPECT_EQ(panels[1].unit, "V");
  EXPECT_EQ(panels[1].series, (std::vector<std::size_t>{1}));
  EXPECT_EQ(panels[2].unit, "");
  EXPECT_TRUE(panels[2].binary);
}

TEST(PlotPanels, RangesCoverTheFiniteValues) {
  Figure figure = robot();
  figure.series[0].values[1] = std::numeric_limits<double>::infinity();
  const std::vector<Panel> panels = panels_by_unit(figure);
  const Range pitch = value_range(figure, panels[0]);
  EXPECT_NEAR(pitch.low, -0.02 - 0.006, 1e-12);
  EXPECT_NEAR(pitch.high, 0.1 + 0.006, 1e-12);
  EXPECT_NEAR(time_range(figure).high, 0.04, 1e-12);
}

TEST(PlotSvg, DrawsAPanelPerUnitWithLegendsAndTimeAxis) {
  const std::string svg = to_svg(robot());
  EXPECT_EQ(WellFormed{svg}.problem(), "");
  EXPECT_EQ(occurrences(svg, "<g class=\"panel\">"), 3U);
  EXPECT_EQ(occurrences(svg, "<polyline"), 4U);
  for (const char* text : {">Balancing robot<", ">pitch<", ">pitch reference<", ">motor<", ">saturated<", ">rad<",
                           ">V<", ">time [s]<", ">0.040<"}) {
    EXPECT_NE(svg.find(text), std::string::npos) << text;
  }
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("e-17"), std::string::npos);
}

TEST(PlotSvg, SeriesGetDistinctColours) {
  Figure figure{.title = "", .time = {0, 1}, .series = {}};
  for (int i = 0; i < 10; ++i) figure.series.push_back({.name = "s" + std::to_string(i), .unit = "", .values = {0, 2}});
  const std::string svg = to_svg(figure);
  // Each series' colour twice (its line and its legend swatch); after eight colours they come again, dashed.
  for (const char* colour : {"#2f9e44", "#c92a2a", "#7b2cbf", "#0b7285", "#8d5524", "#d6336c"}) {
    EXPECT_EQ(occurrences(svg, std::string{"stroke=\""} + colour), 2U) << colour;
  }
  EXPECT_EQ(occurrences(svg, "stroke=\"#1f5fbf\""), 4U);  // series 1 and 9
  EXPECT_EQ(occurrences(svg, "stroke-dasharray=\"7 3\""), 4U);
}

TEST(PlotSvg, MissingSamplesLeaveGaps) {
  Figure figure{.title = "gaps", .time = {0, 1, 2, 3, 4, 5}, .series = {}};
  figure.series.push_back({.name = "x", .unit = "m", .values = {1, 2, nan, 3, 4, 5}});
  figure.series.push_back(
      {.name = "y", .unit = "m", .values = {1, -std::numeric_limits<double>::infinity(), 2, nan, 1, 1}});
  const std::string svg = to_svg(figure);
  EXPECT_EQ(WellFormed{svg}.problem(), "");
  EXPECT_EQ(occurrences(svg, "<polyline"), 5U);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(PlotSvg, StepsHoldThenJump) {
  Figure figure{.title = "", .time = {0, 1, 2}, .series = {}};
  figure.series.push_back({.name = "x", .unit = "", .values = {0, 10, 10}});
  const std::string svg = to_svg(figure);
  // x from 78 to 876 (399 px per second), y from 34 (10.5) to 204 (-0.5): the 0 held to t = 1, then up to 10,
  // held to the end; the last sample of the constant stretch is merged away.
  EXPECT_NE(svg.find("points=\"78,196.3 477,196.3 477,41.7 876,41.7\""), std::string::npos) << svg;
}

TEST(PlotSvg, ConstantAndAllMissingSeriesStillDraw) {
  Figure figure{.title = "", .time = {0, 1, 2}, .series = {}};
  figure.series.push_back({.name = "still", .unit = "m", .values = {3, 3, 3}});
  figure.series.push_back({.name = "never", .unit = "s", .values = {nan, nan, nan}});
  const std::string svg = to_svg(figure);
  EXPECT_EQ(WellFormed{svg}.problem(), "");
  EXPECT_NE(svg.find(">3.0<"), std::string::npos);  // ticks around the constant
  EXPECT_EQ(occurrences(svg, "<polyline"), 1U);
}

TEST(PlotSvg, EmptyFiguresSayNoData) {
  for (const Figure& figure : {Figure{}, Figure{.title = "t", .time = {}, .series = {{"a", "m", {}}}},
                               Figure{.title = "t", .time = {0, 1}, .series = {}}}) {
    const std::string svg = to_svg(figure);
    EXPECT_EQ(WellFormed{svg}.problem(), "");
    EXPECT_NE(svg.find(">no data<"), std::string::npos);
  }
}

TEST(PlotSvg, EscapesNamesUnitsAndTitle) {
  Figure figure{.title = "a < b & \"c\"", .time = {0, 1}, .series = {}};
  figure.series.push_back({.name = "<script>alert(1)</script>", .unit = "m&s", .values = {0, 1}});
  figure.series.push_back({.name = std::string(60, 'n'), .unit = "'", .values = {0, 1}});
  const std::string svg = to_svg(figure);
  EXPECT_EQ(WellFormed{svg}.problem(), "");
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_NE(svg.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(svg.find(">m&amp;s<"), std::string::npos);
  EXPECT_NE(svg.find(std::string(47, 'n') + "\u2026<"), std::string::npos);  // long names are cut
}

TEST(PlotSvg, MillionsOfSamplesMakeASmallPicture) {
  constexpr std::size_t count = 1'000'000;
  Figure figure{.title = "big", .time = std::vector<double>(count), .series = {}};
  for (std::size_t i = 0; i < count; ++i) figure.time[i] = static_cast<double>(i) * 1e-3;
  for (int s = 0; s < 5; ++s) {
    Series series{.name = "s" + std::to_string(s), .unit = s < 3 ? "m" : "V", .values = std::vector<double>(count)};
    for (std::size_t i = 0; i < count; ++i)
      series.values[i] = std::sin(static_cast<double>(i) * 1e-3 * (s + 1)) + static_cast<double>(i % 7) * 0.1;
    figure.series.push_back(std::move(series));
  }
  figure.series[4].values[777'777] = 50;  // a spike of one sample
  const std::string svg = to_svg(figure);
  EXPECT_LT(svg.size(), 600'000U);
  EXPECT_EQ(WellFormed{svg}.problem(), "");
  EXPECT_NE(svg.find(">50<"), std::string::npos);  // the axis reaches the spike
}

// xmllint, where it is installed, as a second opinion on well-formedness.
TEST(PlotSvg, XmllintAcceptsTheDocument) {
  if (std::system("xmllint --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "xmllint is not installed";
  const std::string file = ::testing::TempDir() + "duet_plot_test.svg";
  Figure figure = robot();
  figure.series[0].name = "\xFF<&>\x01";
  std::ofstream{file} << to_svg(figure);
  EXPECT_EQ(std::system(("xmllint --noout " + file).c_str()), 0);
  std::remove(file.c_str());
}

}  // namespace
}  // namespace duet::plot
