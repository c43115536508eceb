#include "duet/blocks/nonlinear.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace duet::blocks {
namespace {

static_assert(saturate(12, 0, 10) == 10);
static_assert(absolute<std::int8_t>(-128) == 127);
static_assert(absolute(-0.0) == 0.0);
static_assert(select(false, 1.0F, 2.0F) == 2.0F);
static_assert(sign(-3.5) == -1.0 && sign<std::uint8_t>(7) == 1 && sign(0) == 0);
static_assert(minimum(2, -3) == -3 && maximum(2.5F, -3.0F) == 2.5F);
static_assert(dead_zone(2.0, -0.5, 0.5) == 1.5);

TEST(BlocksSaturate, LimitsToTheBoundsAndPassesEverythingBetween) {
  EXPECT_EQ(saturate(11.0, -1.0, 10.0), 10.0);
  EXPECT_EQ(saturate(10.0, -1.0, 10.0), 10.0);
  EXPECT_EQ(saturate(9.5, -1.0, 10.0), 9.5);
  EXPECT_EQ(saturate(-1.0, -1.0, 10.0), -1.0);
  EXPECT_EQ(saturate(-1.5, -1.0, 10.0), -1.0);
  EXPECT_EQ(saturate(std::numeric_limits<float>::infinity(), -1.0F, 1.0F), 1.0F);
  EXPECT_EQ(saturate(-std::numeric_limits<float>::infinity(), -1.0F, 1.0F), -1.0F);
  EXPECT_EQ(saturate<std::int8_t>(-128, -100, 100), -100);
  EXPECT_EQ(saturate<std::uint16_t>(65535, 10, 1000), 1000);
  EXPECT_EQ(saturate<std::uint16_t>(3, 10, 1000), 10);
}

TEST(BlocksSaturate, NanPassesThrough) {
  EXPECT_TRUE(std::isnan(saturate(std::numeric_limits<double>::quiet_NaN(), -1.0, 1.0)));
}

TEST(BlocksSaturate, WithCrossedLimitsUpperIsCheckedFirst) {
  EXPECT_EQ(saturate(5, 10, 0), 0);    // above upper
  EXPECT_EQ(saturate(-5, 10, 0), 10);  // not above upper, below lower
}

TEST(BlocksDeadZone, ZeroInsideShiftedOutside) {
  EXPECT_EQ(dead_zone(0.2, -0.5, 1.0), 0.0);
  EXPECT_EQ(dead_zone(-0.5, -0.5, 1.0), 0.0);  // both ends belong to the zone
  EXPECT_EQ(dead_zone(1.0, -0.5, 1.0), 0.0);
  EXPECT_EQ(dead_zone(1.25, -0.5, 1.0), 0.25);
  EXPECT_EQ(dead_zone(-2.0, -0.5, 1.0), -1.5);
  EXPECT_EQ(dead_zone(3.0F, 1.0F, 2.0F), 1.0F);
  EXPECT_EQ(dead_zone(0.0F, 1.0F, 2.0F), -1.0F);           // a zone that does not hold 0 shifts 0 too
  EXPECT_FALSE(std::signbit(dead_zone(-0.0, -1.0, 1.0)));  // the zone's zero is +0.0
}

TEST(BlocksDeadZone, InfinitiesNanAndAZoneOfOnePoint) {
  const double infinity = std::numeric_limits<double>::infinity();
  EXPECT_EQ(dead_zone(infinity, -1.0, 1.0), infinity);
  EXPECT_EQ(dead_zone(-infinity, -1.0, 1.0), -infinity);
  EXPECT_TRUE(std::isnan(dead_zone(std::numeric_limits<double>::quiet_NaN(), -1.0, 1.0)));
  EXPECT_EQ(dead_zone(2.0, 2.0, 2.0), 0.0);
  EXPECT_EQ(dead_zone(2.5, 2.0, 2.0), 0.5);
  EXPECT_EQ(dead_zone(1.5, 2.0, 2.0), -0.5);
  EXPECT_EQ(dead_zone(5.0, 1.0, -1.0), 6.0);  // crossed: u > end is tested first
  EXPECT_EQ(dead_zone(0.0, 1.0, -1.0), 1.0);  // then u >= start fails: u - start
}

TEST(BlocksAbsolute, IntegersAndTheMostNegativeValue) {
  EXPECT_EQ(absolute<std::int8_t>(-5), 5);
  EXPECT_EQ(absolute<std::int8_t>(5), 5);
  EXPECT_EQ(absolute<std::int8_t>(-128), 127);
  EXPECT_EQ(absolute<std::int8_t>(-127), 127);
  EXPECT_EQ(absolute<std::int16_t>(-32768), 32767);
  EXPECT_EQ(absolute(std::numeric_limits<std::int32_t>::min()), std::numeric_limits<std::int32_t>::max());
  EXPECT_EQ(absolute(-2147483647), 2147483647);
  EXPECT_EQ(absolute<std::uint8_t>(200), 200);
  EXPECT_EQ(absolute<std::uint32_t>(4000000000U), 4000000000U);
}

TEST(BlocksAbsolute, FloatingPointClearsTheSign) {
  EXPECT_EQ(absolute(-2.5), 2.5);
  EXPECT_EQ(absolute(2.5F), 2.5F);
  EXPECT_FALSE(std::signbit(absolute(-0.0)));
  EXPECT_FALSE(std::signbit(absolute(-0.0F)));
  EXPECT_EQ(absolute(-std::numeric_limits<float>::infinity()), std::numeric_limits<float>::infinity());
  EXPECT_EQ(absolute(-std::numeric_limits<double>::denorm_min()), std::numeric_limits<double>::denorm_min());
  const double nan_abs = absolute(-std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(nan_abs));
  EXPECT_FALSE(std::signbit(nan_abs));
}

TEST(BlocksSelect, ChoosesOnOrOff) {
  EXPECT_EQ(select(true, 1.5, -1.5), 1.5);
  EXPECT_EQ(select(false, 1.5, -1.5), -1.5);
  EXPECT_EQ(select<std::int8_t>(true, -128, 127), -128);
  EXPECT_TRUE(select(false, false, true));
}

TEST(BlocksSign, MinusOneZeroOrOne) {
  EXPECT_EQ(sign(-0.25), -1.0);
  EXPECT_EQ(sign(1e-300), 1.0);
  EXPECT_EQ(sign(-std::numeric_limits<float>::infinity()), -1.0F);
  EXPECT_EQ(sign(std::numeric_limits<float>::denorm_min()), 1.0F);
  EXPECT_EQ(sign<std::int8_t>(-128), -1);
  EXPECT_EQ(sign<std::int8_t>(127), 1);
  EXPECT_EQ(sign(std::numeric_limits<std::int32_t>::min()), -1);
  EXPECT_EQ(sign<std::int16_t>(0), 0);
  EXPECT_EQ(sign<std::uint32_t>(0), 0U);
  EXPECT_EQ(sign<std::uint32_t>(4000000000U), 1U);
}

TEST(BlocksSign, ZerosAndNanGivePositiveZero) {
  for (const double u :
       {0.0, -0.0, std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::quiet_NaN()}) {
    const double s = sign(u);
    EXPECT_EQ(s, 0.0) << u;
    EXPECT_FALSE(std::signbit(s)) << u;
  }
  EXPECT_FALSE(std::signbit(sign(-0.0F)));
  EXPECT_EQ(sign(std::numeric_limits<float>::quiet_NaN()), 0.0F);
}

TEST(BlocksMinimumMaximum, PlainValues) {
  EXPECT_EQ(minimum(1.5, -2.0), -2.0);
  EXPECT_EQ(minimum(-2.0, 1.5), -2.0);
  EXPECT_EQ(maximum(1.5, -2.0), 1.5);
  EXPECT_EQ(maximum(-2.0, 1.5), 1.5);
  EXPECT_EQ(minimum<std::int8_t>(-128, 127), -128);
  EXPECT_EQ(maximum<std::int8_t>(-128, 127), 127);
  EXPECT_EQ(minimum<std::uint16_t>(65535, 3), 3);
  EXPECT_EQ(maximum<std::uint32_t>(0, 4000000000U), 4000000000U);
  EXPECT_EQ(minimum(-std::numeric_limits<float>::infinity(), 0.0F), -std::numeric_limits<float>::infinity());
  EXPECT_EQ(maximum(std::numeric_limits<float>::infinity(), 0.0F), std::numeric_limits<float>::infinity());
}

TEST(BlocksMinimumMaximum, OneNanGivesTheOtherOperand) {
  const double nan_value = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(minimum(nan_value, 3.0), 3.0);
  EXPECT_EQ(minimum(3.0, nan_value), 3.0);
  EXPECT_EQ(maximum(nan_value, -3.0), -3.0);
  EXPECT_EQ(maximum(-3.0, nan_value), -3.0);
  const float nan_float = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(minimum(nan_float, -1.0F), -1.0F);
  EXPECT_EQ(maximum(2.0F, nan_float), 2.0F);
  EXPECT_TRUE(std::isnan(minimum(nan_value, nan_value)));
  EXPECT_TRUE(std::isnan(maximum(nan_float, nan_float)));
}

TEST(BlocksMinimumMaximum, EqualOperandsGiveTheFirst) {
  EXPECT_FALSE(std::signbit(minimum(0.0, -0.0)));
  EXPECT_TRUE(std::signbit(minimum(-0.0, 0.0)));
  EXPECT_FALSE(std::signbit(maximum(0.0F, -0.0F)));
  EXPECT_TRUE(std::signbit(maximum(-0.0F, 0.0F)));
}

}  // namespace
}  // namespace duet::blocks
