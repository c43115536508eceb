#include "duet/blocks/trigonometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <string>

namespace duet::blocks {
namespace {

constexpr double pi = std::numbers::pi;
constexpr float pi_f = std::numbers::pi_v<float>;

static_assert(atan2(0.0, 1.0) == 0.0);
static_assert(atan2(1.0F, 0.0F) == static_cast<float>(pi / 2));
static_assert(atan2(-0.0, -1.0) == -pi);
static_assert(radians(180.0) > 3.14 && degrees(radians(90.0F)) > 89.99F);

// The largest difference from the C library's double atan2 (the reference, for float inputs too) over a grid of
// points on squares around the origin, from tiny to huge, so every octant, both axes and the diagonals are crossed.
template <typename T>
double largest_error_on_grid() {
  double largest = 0.0;
  constexpr int steps = 400;  // points per side of each square
  for (const double scale : {1e-30, 1e-3, 0.7, 1.0, 3.0, 1e4, 1e30}) {
    for (int i = -steps; i <= steps; ++i) {
      for (int j = -steps; j <= steps; ++j) {
        const auto y = static_cast<T>(scale * i / steps);
        const auto x = static_cast<T>(scale * j / steps);
        const double error =
            std::fabs(static_cast<double>(atan2(y, x)) - std::atan2(static_cast<double>(y), static_cast<double>(x)));
        if (error > largest) largest = error;
      }
    }
  }
  // And the unit circle, one million points, where the angle sweeps continuously.
  constexpr int points = 1000000;
  for (int k = 0; k < points; ++k) {
    const double angle = -pi + 2 * pi * k / points;
    const auto y = static_cast<T>(std::sin(angle));
    const auto x = static_cast<T>(std::cos(angle));
    const double error =
        std::fabs(static_cast<double>(atan2(y, x)) - std::atan2(static_cast<double>(y), static_cast<double>(x)));
    if (error > largest) largest = error;
  }
  return largest;
}

TEST(BlocksAtan2, FloatIsWithinFourTenthsOfAMicroradian) {
  const double error = largest_error_on_grid<float>();
  RecordProperty("largest_error_rad", std::to_string(error));
  EXPECT_LE(error, 4e-7);
}

TEST(BlocksAtan2, DoubleIsWithinOneTenthOfAPicoradian) {
  const double error = largest_error_on_grid<double>();
  RecordProperty("largest_error_rad", std::to_string(error));
  EXPECT_LE(error, 1e-13);
}

TEST(BlocksAtan2, ReductionConstantsAreAtanOfEighthsToTheLastBit) {
  for (std::size_t k = 0; k < detail::atan_of_eighths.size(); ++k) {
    EXPECT_NEAR(detail::atan_of_eighths[k], std::atan(static_cast<double>(k) / 8.0), 2.3e-16) << k;
  }
}

TEST(BlocksAtan2, Quadrants) {
  EXPECT_NEAR(atan2(1.0, 1.0), pi / 4, 1e-15);
  EXPECT_NEAR(atan2(1.0, -1.0), 3 * pi / 4, 1e-15);
  EXPECT_NEAR(atan2(-1.0, -1.0), -3 * pi / 4, 1e-15);
  EXPECT_NEAR(atan2(-1.0, 1.0), -pi / 4, 1e-15);
  EXPECT_NEAR(atan2(2.0F, -1.0F), std::atan2(2.0, -1.0), 3e-7);
  EXPECT_NEAR(atan2(-1e-3, -1.0), -pi + 1e-3, 1e-9);
  // Near +-pi the float result never leaves [-pi_f, pi_f].
  EXPECT_LE(atan2(1e-30F, -1.0F), pi_f);
  EXPECT_GE(atan2(-1e-30F, -1.0F), -pi_f);
}

TEST(BlocksAtan2, SignedZerosAndAxes) {
  EXPECT_EQ(atan2(0.0, 0.0), 0.0);
  EXPECT_FALSE(std::signbit(atan2(0.0, 0.0)));
  EXPECT_TRUE(std::signbit(atan2(-0.0, 0.0)));
  EXPECT_EQ(atan2(-0.0, 0.0), 0.0);
  EXPECT_FALSE(std::signbit(atan2(0.0F, 5.0F)));
  EXPECT_TRUE(std::signbit(atan2(-0.0F, 5.0F)));
  EXPECT_EQ(atan2(0.0, -0.0), pi);
  EXPECT_EQ(atan2(-0.0, -0.0), -pi);
  EXPECT_EQ(atan2(0.0F, -2.0F), pi_f);
  EXPECT_EQ(atan2(-0.0F, -2.0F), -pi_f);
  EXPECT_EQ(atan2(3.0, 0.0), pi / 2);
  EXPECT_EQ(atan2(3.0, -0.0), pi / 2);
  EXPECT_EQ(atan2(-3.0, 0.0), -pi / 2);
  EXPECT_EQ(atan2(1e-30F, 0.0F), pi_f / 2);
  EXPECT_EQ(atan2(-std::numeric_limits<float>::denorm_min(), 0.0F), -pi_f / 2);
}

TEST(BlocksAtan2, Infinities) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  EXPECT_NEAR(atan2(inf, inf), pi / 4, 1e-16);
  EXPECT_NEAR(atan2(-inf, inf), -pi / 4, 1e-16);
  EXPECT_NEAR(atan2(inf, -inf), 3 * pi / 4, 1e-15);
  EXPECT_NEAR(atan2(-inf, -inf), -3 * pi / 4, 1e-15);
  EXPECT_EQ(atan2(inf, 1.0), pi / 2);
  EXPECT_EQ(atan2(-inf, -1e300), -pi / 2);
  EXPECT_EQ(atan2(1.0, inf), 0.0);
  EXPECT_TRUE(std::signbit(atan2(-1.0, inf)));
  EXPECT_EQ(atan2(1.0, -inf), pi);
  EXPECT_EQ(atan2(-1.0F, -std::numeric_limits<float>::infinity()), -pi_f);
}

TEST(BlocksAtan2, NanInNanOut) {
  constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(atan2(nan_value, 1.0)));
  EXPECT_TRUE(std::isnan(atan2(1.0, nan_value)));
  EXPECT_TRUE(std::isnan(atan2(nan_value, nan_value)));
  EXPECT_TRUE(std::isnan(atan2(0.0F, std::numeric_limits<float>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(atan2(std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN())));
}

TEST(BlocksAngleUnits, DegreesAndRadians) {
  EXPECT_NEAR(degrees(pi), 180.0, 1e-13);
  EXPECT_NEAR(degrees(pi_f), 180.0F, 2e-5F);
  EXPECT_NEAR(radians(180.0), pi, 1e-15);
  EXPECT_NEAR(radians(-90.0F), -pi_f / 2, 2e-7F);
  EXPECT_EQ(degrees(0.0), 0.0);
  EXPECT_NEAR(radians(degrees(1.234)), 1.234, 1e-15);
  EXPECT_DOUBLE_EQ(degrees(1.0), 180.0 / pi);
}

}  // namespace
}  // namespace duet::blocks
