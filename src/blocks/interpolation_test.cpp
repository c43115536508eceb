#include "duet/blocks/interpolation.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace duet::blocks {
namespace {

constexpr std::array<double, 4> breakpoints{0.0, 1.0, 3.0, 4.0};
constexpr std::array<double, 4> table{10.0, 20.0, 0.0, 5.0};
constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

double at(InterpolationMethod method, Extrapolation extrapolation, double u) {
  return interpolate(method, extrapolation, std::span<const double>(breakpoints), std::span<const double>(table), u);
}

static_assert(interpolate(InterpolationMethod::linear, Extrapolation::clip, std::span<const double>(breakpoints),
                          std::span<const double>(table), 2.0) == 10.0);

TEST(BlocksInterpolate, LinearBetweenAndExactlyOnBreakpoints) {
  using enum InterpolationMethod;
  EXPECT_EQ(at(linear, Extrapolation::clip, 0.0), 10.0);
  EXPECT_EQ(at(linear, Extrapolation::clip, 0.5), 15.0);  // (20 - 10) * 0.5 + 10
  EXPECT_EQ(at(linear, Extrapolation::clip, 1.0), 20.0);  // an inner breakpoint starts the next segment: f = 0
  EXPECT_EQ(at(linear, Extrapolation::clip, 2.0), 10.0);  // (0 - 20) * 0.5 + 20
  EXPECT_EQ(at(linear, Extrapolation::clip, 3.0), 0.0);
  EXPECT_EQ(at(linear, Extrapolation::clip, 3.5), 2.5);  // (5 - 0) * 0.5 + 0
  EXPECT_EQ(at(linear, Extrapolation::clip, 4.0), 5.0);
}

TEST(BlocksInterpolate, ClipHoldsTheEndsAndLinearContinuesTheEndSegments) {
  using enum InterpolationMethod;
  EXPECT_EQ(at(linear, Extrapolation::clip, -1.0), 10.0);
  EXPECT_EQ(at(linear, Extrapolation::clip, 10.0), 5.0);
  EXPECT_EQ(at(linear, Extrapolation::clip, -infinity), 10.0);
  EXPECT_EQ(at(linear, Extrapolation::clip, infinity), 5.0);
  EXPECT_EQ(at(linear, Extrapolation::linear, -1.0), 0.0);  // f = -1: 10 * -1 + 10
  EXPECT_EQ(at(linear, Extrapolation::linear, 6.0), 15.0);  // f = 3: 5 * 3 + 0
  EXPECT_EQ(at(linear, Extrapolation::linear, 0.0), 10.0);  // the ends themselves are not extrapolated
  EXPECT_EQ(at(linear, Extrapolation::linear, 4.0), 5.0);
  EXPECT_EQ(at(linear, Extrapolation::linear, infinity), infinity);
  EXPECT_EQ(at(linear, Extrapolation::linear, -infinity), -infinity);
  // A flat end segment times an infinite fraction: 0 * inf.
  constexpr std::array<double, 2> level{1.0, 1.0};
  constexpr std::array<double, 2> two{0.0, 1.0};
  EXPECT_TRUE(std::isnan(interpolate(InterpolationMethod::linear, Extrapolation::linear, std::span<const double>(two),
                                     std::span<const double>(level), infinity)));
}

TEST(BlocksInterpolate, NanIsPlacedAboveTheLastBreakpoint) {
  using enum InterpolationMethod;
  EXPECT_EQ(at(linear, Extrapolation::clip, nan_value), 5.0);
  EXPECT_TRUE(std::isnan(at(linear, Extrapolation::linear, nan_value)));
  EXPECT_EQ(at(nearest, Extrapolation::clip, nan_value), 5.0);
  EXPECT_EQ(at(flat, Extrapolation::clip, nan_value), 5.0);
  EXPECT_EQ(at(above, Extrapolation::clip, nan_value), 5.0);
}

// The fraction first, then the product: Simulink's order, which can differ from (dt * du) / db in the last bit.
TEST(BlocksInterpolate, RoundsTheFractionFirstAsSimulinkDoes) {
  constexpr std::array<double, 2> span_0_9{0.0, 9.0};
  constexpr std::array<double, 2> rise{0.0, 0.7};
  const double y = interpolate(InterpolationMethod::linear, Extrapolation::clip, std::span<const double>(span_0_9),
                               std::span<const double>(rise), 6.0);
  EXPECT_EQ(y, 0.7 * (6.0 / 9.0));
  EXPECT_NE(y, 0.7 * 6.0 / 9.0);
  constexpr std::array<double, 2> span_0_3{0.0, 3.0};
  constexpr std::array<double, 2> small_rise{0.0, 0.2};
  const double extrapolated = interpolate(InterpolationMethod::linear, Extrapolation::linear,
                                          std::span<const double>(span_0_3), std::span<const double>(small_rise), 5.0);
  EXPECT_EQ(extrapolated, 0.33333333333333337);
  // At and above the last breakpoint, clipping computes (t1 - t0) * 1 + t0, which need not be t1 exactly.
  constexpr std::array<double, 2> fall{0.7, 0.1};
  const double clipped = interpolate(InterpolationMethod::linear, Extrapolation::clip,
                                     std::span<const double>(span_0_3), std::span<const double>(fall), 3.0);
  EXPECT_EQ(clipped, (0.1 - 0.7) + 0.7);
  EXPECT_NE(clipped, 0.1);
}

TEST(BlocksInterpolate, NearestTakesTheUpperBreakpointWhenMidway) {
  using enum InterpolationMethod;
  EXPECT_EQ(at(nearest, Extrapolation::clip, -5.0), 10.0);
  EXPECT_EQ(at(nearest, Extrapolation::clip, 0.49), 10.0);
  EXPECT_EQ(at(nearest, Extrapolation::clip, 0.5), 20.0);
  EXPECT_EQ(at(nearest, Extrapolation::clip, 1.9), 20.0);
  EXPECT_EQ(at(nearest, Extrapolation::clip, 2.0), 0.0);
  EXPECT_EQ(at(nearest, Extrapolation::clip, 3.0), 0.0);
  EXPECT_EQ(at(nearest, Extrapolation::clip, 9.0), 5.0);
  EXPECT_EQ(at(nearest, Extrapolation::linear, 9.0), 5.0);  // only linear interpolation extrapolates
}

TEST(BlocksInterpolate, FlatTakesTheBreakpointAtOrBelowAndAboveTheOneAtOrAbove) {
  using enum InterpolationMethod;
  EXPECT_EQ(at(flat, Extrapolation::clip, -1.0), 10.0);
  EXPECT_EQ(at(flat, Extrapolation::clip, 0.99), 10.0);
  EXPECT_EQ(at(flat, Extrapolation::clip, 1.0), 20.0);
  EXPECT_EQ(at(flat, Extrapolation::clip, 2.9), 20.0);
  EXPECT_EQ(at(flat, Extrapolation::clip, 3.0), 0.0);
  EXPECT_EQ(at(flat, Extrapolation::clip, 4.0), 5.0);
  EXPECT_EQ(at(flat, Extrapolation::linear, 100.0), 5.0);
  EXPECT_EQ(at(above, Extrapolation::clip, -1.0), 10.0);
  EXPECT_EQ(at(above, Extrapolation::clip, 0.0), 10.0);
  EXPECT_EQ(at(above, Extrapolation::clip, 0.01), 20.0);
  EXPECT_EQ(at(above, Extrapolation::clip, 1.0), 20.0);
  EXPECT_EQ(at(above, Extrapolation::clip, 1.01), 0.0);
  EXPECT_EQ(at(above, Extrapolation::clip, 3.5), 5.0);
  EXPECT_EQ(at(above, Extrapolation::clip, infinity), 5.0);
}

TEST(BlocksInterpolate, FloatComputesInFloat) {
  constexpr std::array<float, 3> b{-1.0F, 0.0F, 2.0F};
  constexpr std::array<float, 3> t{-3.0F, 1.0F, 2.0F};
  const auto y = [&](float u) {
    return interpolate(InterpolationMethod::linear, Extrapolation::linear, std::span<const float>(b),
                       std::span<const float>(t), u);
  };
  EXPECT_EQ(y(-0.5F), -1.0F);  // 4 * 0.5 - 3
  EXPECT_EQ(y(1.0F), 1.5F);    // 1 * 0.5 + 1
  EXPECT_EQ(y(4.0F), 3.0F);    // 1 * 2 + 1
  EXPECT_EQ(y(-2.0F), -7.0F);  // 4 * -1 - 3
}

TEST(BlocksInterpolate, SearchesLargeTablesAndSurvivesBrokenPreconditions) {
  std::array<double, 1000> squares_at{};
  std::array<double, 1000> values{};
  for (std::size_t k = 0; k < squares_at.size(); ++k) {
    squares_at[k] = static_cast<double>(k);
    values[k] = static_cast<double>(k * k);
  }
  for (std::size_t k = 0; k + 1 < squares_at.size(); k += 37) {
    const double u = static_cast<double>(k) + 0.5;
    EXPECT_EQ(interpolate(InterpolationMethod::linear, Extrapolation::clip, std::span<const double>(squares_at),
                          std::span<const double>(values), u),
              static_cast<double>(k * k) + static_cast<double>(2 * k + 1) * 0.5)
        << k;
    EXPECT_EQ(interpolate(InterpolationMethod::flat, Extrapolation::clip, std::span<const double>(squares_at),
                          std::span<const double>(values), u),
              static_cast<double>(k * k))
        << k;
  }
  // Breakpoints out of order still give one of the table's values, never a read outside it.
  constexpr std::array<double, 4> unsorted{3.0, 0.0, 5.0, 1.0};
  const double y = interpolate(InterpolationMethod::flat, Extrapolation::clip, std::span<const double>(unsorted),
                               std::span<const double>(table), 2.0);
  EXPECT_TRUE(y == 10.0 || y == 20.0 || y == 0.0 || y == 5.0) << y;
  // Sizes the checker refuses give 0.
  EXPECT_EQ(interpolate(InterpolationMethod::linear, Extrapolation::clip, std::span<const double>(breakpoints),
                        std::span<const double>(table).first(3), 1.0),
            0.0);
  EXPECT_EQ(interpolate(InterpolationMethod::nearest, Extrapolation::clip,
                        std::span<const double>(breakpoints).first(1), std::span<const double>(table).first(1), 1.0),
            0.0);
}

}  // namespace
}  // namespace duet::blocks
