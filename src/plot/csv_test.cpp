#include "duet/plot/csv.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "well_formed.hpp"

namespace duet::plot {
namespace {

TEST(PlotCsv, ReadsWhatTheSimulationWrites) {
  const Result<Figure> figure = read_csv("time_s,angle,motor[0]\n0,0.5,1\n0.001,-2.5e-3,0\n0.002,nan,1\n", "run.csv");
  ASSERT_TRUE(figure.ok()) << figure.error();
  EXPECT_EQ(figure.value().title, "run.csv");
  EXPECT_EQ(figure.value().time_unit, "s");
  EXPECT_EQ(figure.value().time, (std::vector<double>{0, 0.001, 0.002}));
  ASSERT_EQ(figure.value().series.size(), 2U);
  EXPECT_EQ(figure.value().series[0].name, "angle");
  EXPECT_EQ(figure.value().series[0].unit, "");
  EXPECT_DOUBLE_EQ(figure.value().series[0].values[1], -2.5e-3);
  EXPECT_TRUE(std::isnan(figure.value().series[0].values[2]));
  EXPECT_EQ(figure.value().series[1].name, "motor[0]");
  EXPECT_EQ(figure.value().series[1].values, (std::vector<double>{1, 0, 1}));
}

TEST(PlotCsv, ToleratesSpacesCrLfBlankLinesAndEmptyValues) {
  const Result<Figure> figure = read_csv("time_ms , a\r\n\r\n 0 , +1 \r\n5,\r\n10,-inf\r\n\r\n", "x.csv");
  ASSERT_TRUE(figure.ok()) << figure.error();
  EXPECT_EQ(figure.value().time_unit, "ms");
  EXPECT_EQ(figure.value().series[0].name, "a");
  EXPECT_EQ(figure.value().series[0].values[0], 1);
  EXPECT_TRUE(std::isnan(figure.value().series[0].values[1]));  // empty: a missing sample
  EXPECT_TRUE(std::isinf(figure.value().series[0].values[2]));
}

TEST(PlotCsv, AHeaderAloneIsAFigureWithoutSamples) {
  const Result<Figure> figure = read_csv("time,a,b", "x.csv");
  ASSERT_TRUE(figure.ok()) << figure.error();
  EXPECT_EQ(figure.value().time_unit, "");
  EXPECT_EQ(figure.value().series.size(), 2U);
  EXPECT_TRUE(figure.value().time.empty());
}

TEST(PlotCsv, ErrorsNameTheLineAndColumn) {
  const auto error = [](const std::string& text) {
    const Result<Figure> figure = read_csv(text, "run.csv");
    return figure.ok() ? std::string{"(no error)"} : figure.error();
  };
  EXPECT_EQ(error(""), "run.csv:1: no header; expected one such as time_s,a,b");
  EXPECT_EQ(error("angle,rate\n1,2\n"), "run.csv:1: the first column is 'angle'; expected the time, as time_s");
  EXPECT_EQ(error("time_s,a,,b\n"), "run.csv:1: column 3 has no name");
  EXPECT_EQ(error("time_s,a,b\n0,1,2\n0.1,1\n"), "run.csv:3: 2 values; expected 3, one per column of the header");
  EXPECT_EQ(error("time_s,a,b\n0,1,2\n0.1,1,2,3\n"), "run.csv:3: 4 values; expected 3, one per column of the header");
  EXPECT_EQ(error("time_s,a,b\n0,1,2\n\n0.1,1,x2\n"), "run.csv:4: column 3 (b): 'x2' is not a number");
  EXPECT_EQ(error("time_s,a\n0,1.5.2\n"), "run.csv:2: column 2 (a): '1.5.2' is not a number");
  EXPECT_EQ(error("time_s,a\n,1\n"), "run.csv:2: column 1 (time_s): '' is not a finite number");
  EXPECT_EQ(error("time_s,a\nnan,1\n"), "run.csv:2: column 1 (time_s): 'nan' is not a finite number");
  EXPECT_EQ(error("time_s,a\n0.2,1\n0.1,1\n"), "run.csv:3: the time 0.1 is before the time of the row above");
}

TEST(PlotCsv, WhatIsReadCanBePlotted) {
  Result<Figure> figure = read_csv("time_s,a,b\n0,1,0\n0.5,2,1\n1,,1\n1.5,3,0\n", "run.csv");
  ASSERT_TRUE(figure.ok()) << figure.error();
  figure.value().series[1].unit = "flag";
  const std::string svg = to_svg(figure.value());
  EXPECT_EQ(WellFormed{svg}.problem(), "");
  EXPECT_NE(svg.find(">run.csv<"), std::string::npos);
}

}  // namespace
}  // namespace duet::plot
