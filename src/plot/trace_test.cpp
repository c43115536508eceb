#include "trace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace duet::plot {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::vector<double> counting(std::size_t count) {
  std::vector<double> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = static_cast<double>(i);
  return values;
}

TEST(PlotTrace, FewSamplesAreKeptAsTheyAre) {
  const std::vector<double> time{0, 1, 2, 3};
  const std::vector<double> values{5, 6, 5, 7};
  const std::vector<Trace> lines = trace(time, values, {.time_low = 0, .time_high = 3, .width = 300});
  ASSERT_EQ(lines.size(), 1U);
  ASSERT_EQ(lines[0].points.size(), 4U);
  EXPECT_DOUBLE_EQ(lines[0].points[2].x, 200);
  EXPECT_DOUBLE_EQ(lines[0].points[3].value, 7);
  EXPECT_FALSE(lines[0].end_x);  // the last sample ends the series, not a gap
}

TEST(PlotTrace, MissingSamplesSplitTheLine) {
  const std::vector<double> time{0, 1, 2, 3, 4, 5, 6};
  const std::vector<double> values{1, 2, nan, 4, std::numeric_limits<double>::infinity(), 6, 7};
  const std::vector<Trace> lines = trace(time, values, {.time_low = 0, .time_high = 6, .width = 600});
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[0].points.size(), 2U);
  ASSERT_TRUE(lines[0].end_x);
  EXPECT_DOUBLE_EQ(*lines[0].end_x, 200);  // the value 2 holds until the missing sample's time
  EXPECT_EQ(lines[1].points.size(), 1U);
  EXPECT_EQ(lines[2].points.size(), 2U);
}

TEST(PlotTrace, AMissingTimeIsAGapToo) {
  const std::vector<double> time{0, 1, nan, 3};
  const std::vector<double> values{1, 2, 3, 4};
  EXPECT_EQ(trace(time, values, {.time_low = 0, .time_high = 3, .width = 30}).size(), 2U);
}

TEST(PlotTrace, DrawsAsManySamplesAsTimeAndValuesBothHave) {
  const std::vector<double> time{0, 1, 2};
  const std::vector<double> values{1, 2, 3, 4, 5};
  const std::vector<Trace> lines = trace(time, values, {.time_low = 0, .time_high = 2, .width = 20});
  ASSERT_EQ(lines.size(), 1U);
  EXPECT_EQ(lines[0].points.size(), 3U);
}

TEST(PlotTrace, DecimationKeepsASingleSampleSpike) {
  constexpr std::size_t count = 1'000'000;
  const std::vector<double> time = counting(count);
  std::vector<double> values(count, 0.0);
  values[612'345] = 10;
  values[300'001] = -3;
  const double width = 800;
  const std::vector<Trace> lines =
      trace(time, values, {.time_low = 0, .time_high = static_cast<double>(count - 1), .width = width});
  ASSERT_EQ(lines.size(), 1U);
  const std::vector<TracePoint>& points = lines[0].points;
  EXPECT_LE(points.size(), 4 * (static_cast<std::size_t>(width) + 1));
  const auto spike = std::find_if(points.begin(), points.end(), [](const TracePoint& p) { return p.value == 10; });
  ASSERT_NE(spike, points.end());
  EXPECT_NEAR(spike->x, 612'345.0 / static_cast<double>(count - 1) * width, 1e-9);  // at its own time, not the column's
  EXPECT_NE(std::find_if(points.begin(), points.end(), [](const TracePoint& p) { return p.value == -3; }),
            points.end());
  // The points stay in sample order, so the step line runs left to right.
  EXPECT_TRUE(
      std::is_sorted(points.begin(), points.end(), [](const TracePoint& a, const TracePoint& b) { return a.x < b.x; }));
}

TEST(PlotTrace, DecimationKeepsTheOrderOfTheExtremes) {
  // Eight samples in one column: the largest comes before the smallest, and so it must stay.
  const std::vector<double> time{0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7};
  const std::vector<double> values{1, 9, 2, 3, -4, 2, 1, 5};
  const std::vector<Trace> lines = trace(time, values, {.time_low = 0, .time_high = 100, .width = 10});
  ASSERT_EQ(lines.size(), 1U);
  std::vector<double> kept;
  for (const TracePoint& point : lines[0].points) kept.push_back(point.value);
  EXPECT_EQ(kept, (std::vector<double>{1, 9, -4, 5}));
}

}  // namespace
}  // namespace duet::plot
