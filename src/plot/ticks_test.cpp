#include "ticks.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace duet::plot {
namespace {

std::vector<std::string> labels(const Ticks& ticks) {
  std::vector<std::string> out;
  for (const Tick& tick : ticks.ticks) out.push_back(tick.label);
  return out;
}

TEST(PlotTicks, ZeroToOneInFifths) {
  const Ticks ticks = choose_ticks({0, 1}, 6);
  EXPECT_DOUBLE_EQ(ticks.step, 0.2);
  EXPECT_THAT(labels(ticks), ::testing::ElementsAre("0.0", "0.2", "0.4", "0.6", "0.8", "1.0"));
  EXPECT_DOUBLE_EQ(ticks.ticks.back().value, 1.0);
}

TEST(PlotTicks, TakesTheFinestStepThatFits) {
  // -3.7 .. 12 spans 15.7: steps of 2 give eight ticks, too many for six, so 5.
  EXPECT_THAT(labels(choose_ticks({-3.7, 12}, 6)), ::testing::ElementsAre("0", "5", "10"));
  EXPECT_THAT(labels(choose_ticks({-3.7, 12}, 10)), ::testing::ElementsAre("-2", "0", "2", "4", "6", "8", "10", "12"));
  // The padded range of that data still gets round ticks.
  EXPECT_THAT(labels(choose_ticks(padded_range(-3.7, 12), 10)),
              ::testing::ElementsAre("-4", "-2", "0", "2", "4", "6", "8", "10", "12"));
}

TEST(PlotTicks, MicroScaleIsScientificWithoutNoise) {
  EXPECT_THAT(labels(choose_ticks({0, 3e-6}, 6)), ::testing::ElementsAre("0", "1e-6", "2e-6", "3e-6"));
  EXPECT_THAT(labels(choose_ticks({1e-6, 1.6e-6}, 6)), ::testing::ElementsAre("1e-6", "1.2e-6", "1.4e-6", "1.6e-6"));
  EXPECT_THAT(labels(choose_ticks({-2.5e-6, 0}, 6)),
              ::testing::ElementsAre("-2.5e-6", "-2e-6", "-1.5e-6", "-1e-6", "-5e-7", "0"));
}

TEST(PlotTicks, SumsOfTenthsPrintAsTenths) {
  // 0.1 + 0.2 is 0.30000000000000004 in a double; labels come from integers and never show it.
  EXPECT_THAT(labels(choose_ticks({0.1, 0.5}, 5)), ::testing::ElementsAre("0.1", "0.2", "0.3", "0.4", "0.5"));
  EXPECT_THAT(labels(choose_ticks({0, 1e7}, 6)), ::testing::ElementsAre("0", "2e6", "4e6", "6e6", "8e6", "1e7"));
  EXPECT_THAT(labels(choose_ticks({0, 2500}, 6)), ::testing::ElementsAre("0", "500", "1000", "1500", "2000", "2500"));
}

TEST(PlotTicks, ConstantDataGetsARangeAroundIt) {
  const Range five = padded_range(5, 5);
  EXPECT_DOUBLE_EQ(five.low, 4.5);
  EXPECT_DOUBLE_EQ(five.high, 5.5);
  EXPECT_THAT(labels(choose_ticks(five, 6)), ::testing::ElementsAre("4.6", "4.8", "5.0", "5.2", "5.4"));
  const Range zero = padded_range(0, 0);
  EXPECT_DOUBLE_EQ(zero.low, -1);
  EXPECT_DOUBLE_EQ(zero.high, 1);
  // Rounding noise around a value is no range either.
  const Range noisy = padded_range(0.3, 0.1 + 0.2);
  EXPECT_LT(noisy.low, 0.28);
  EXPECT_EQ(usable_range(2, 2).low, 1.8);
}

TEST(PlotTicks, PaddingLeavesAMarginAndStaysFinite) {
  const Range range = padded_range(0, 10);
  EXPECT_DOUBLE_EQ(range.low, -0.5);
  EXPECT_DOUBLE_EQ(range.high, 10.5);
  const Range huge = padded_range(-1.7e308, 1.7e308);
  EXPECT_TRUE(std::isfinite(huge.low) && std::isfinite(huge.high));
  EXPECT_FALSE(choose_ticks(huge, 6).ticks.empty());
  EXPECT_FALSE(choose_ticks(padded_range(1e-300, 3e-300), 6).ticks.empty());
}

TEST(PlotTicks, DecimalLabels) {
  EXPECT_EQ(decimal_label(25, -2), "0.25");
  EXPECT_EQ(decimal_label(-5, -3), "-0.005");
  EXPECT_EQ(decimal_label(0, -2), "0.00");
  EXPECT_EQ(decimal_label(15, 2), "1500");
  EXPECT_EQ(decimal_label(15, -7), "1.5e-6");
  EXPECT_EQ(decimal_label(20, 8), "2e9");
  EXPECT_EQ(decimal_label(-1, -5), "-1e-5");
}

}  // namespace
}  // namespace duet::plot
