#include "duet/blocks/convert.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace duet::blocks {
namespace {

template <typename T>
using Limits = std::numeric_limits<T>;

constexpr double nan_value = Limits<double>::quiet_NaN();
constexpr double infinity = Limits<double>::infinity();

static_assert(convert<std::int8_t>(300) == 127);
static_assert(convert<std::uint8_t>(-2.5) == 0);
static_assert(convert<std::int16_t>(Limits<double>::infinity()) == 32767);
static_assert(convert<std::int32_t>(Limits<float>::quiet_NaN()) == 0);
static_assert(convert<float>(true) == 1.0F);
static_assert(convert<bool>(-0.5F));

// Every pair of element types compiles (and passes the warnings) and agrees on 0 and 1.
template <typename To, typename From>
void expect_converts_zero_and_one() {
  EXPECT_EQ(convert<To>(static_cast<From>(0)), static_cast<To>(0));
  EXPECT_EQ(convert<To>(static_cast<From>(1)), static_cast<To>(1));
}

template <typename To, typename... From>
void expect_converts_zero_and_one_from() {
  (expect_converts_zero_and_one<To, From>(), ...);
}

template <typename... To>
void expect_all_pairs_convert() {
  (expect_converts_zero_and_one_from<To, double, float, std::int8_t, std::int16_t, std::int32_t, std::uint8_t,
                                     std::uint16_t, std::uint32_t, bool>(),
   ...);
}

TEST(BlocksConvert, EveryPairOfElementTypesConverts) {
  expect_all_pairs_convert<double, float, std::int8_t, std::int16_t, std::int32_t, std::uint8_t, std::uint16_t,
                           std::uint32_t, bool, std::int64_t>();
}

TEST(BlocksConvert, SameTypeIsIdentity) {
  EXPECT_EQ(convert<float>(1.5F), 1.5F);
  EXPECT_EQ(convert<std::int8_t>(std::int8_t{-3}), -3);
  EXPECT_TRUE(std::isnan(convert<double>(nan_value)));
  EXPECT_TRUE(std::signbit(convert<double>(-0.0)));
}

TEST(BlocksConvert, ToBoolIsNotEqualToZero) {
  EXPECT_FALSE(convert<bool>(0.0));
  EXPECT_FALSE(convert<bool>(-0.0F));
  EXPECT_TRUE(convert<bool>(1e-300));
  EXPECT_TRUE(convert<bool>(nan_value));
  EXPECT_FALSE(convert<bool>(std::int32_t{0}));
  EXPECT_TRUE(convert<bool>(std::int8_t{-128}));
  EXPECT_TRUE(convert<bool>(std::uint8_t{255}));
}

TEST(BlocksConvert, FromBoolIsZeroOrOne) {
  EXPECT_EQ(convert<double>(true), 1.0);
  EXPECT_EQ(convert<float>(false), 0.0F);
  EXPECT_EQ(convert<std::int8_t>(true), 1);
  EXPECT_EQ(convert<std::uint32_t>(false), 0U);
}

TEST(BlocksConvert, FloatingToIntegerTruncatesTowardZero) {
  EXPECT_EQ(convert<std::int8_t>(1.9), 1);
  EXPECT_EQ(convert<std::int8_t>(-1.9), -1);
  EXPECT_EQ(convert<std::int16_t>(-0.999F), 0);
  EXPECT_EQ(convert<std::uint8_t>(-0.5), 0);
  EXPECT_EQ(convert<std::int32_t>(-123456.75), -123456);
  EXPECT_EQ(convert<std::uint16_t>(65535.99F), 65535);
}

TEST(BlocksConvert, FloatingToIntegerSaturatesAtTheTargetsRange) {
  EXPECT_EQ(convert<std::int8_t>(127.9), 127);
  EXPECT_EQ(convert<std::int8_t>(128.0), 127);
  EXPECT_EQ(convert<std::int8_t>(-128.9), -128);
  EXPECT_EQ(convert<std::int8_t>(-129.0), -128);
  EXPECT_EQ(convert<std::uint8_t>(255.9F), 255);
  EXPECT_EQ(convert<std::uint8_t>(256.0F), 255);
  EXPECT_EQ(convert<std::uint8_t>(-1.0), 0);
  EXPECT_EQ(convert<std::uint8_t>(-1e30), 0);
  EXPECT_EQ(convert<std::int32_t>(2147483647.0), Limits<std::int32_t>::max());
  EXPECT_EQ(convert<std::int32_t>(2147483647.5), Limits<std::int32_t>::max());
  EXPECT_EQ(convert<std::int32_t>(2147483648.0), Limits<std::int32_t>::max());
  EXPECT_EQ(convert<std::int32_t>(-2147483648.0), Limits<std::int32_t>::min());
  EXPECT_EQ(convert<std::int32_t>(-2147483648.9), Limits<std::int32_t>::min());
  EXPECT_EQ(convert<std::int32_t>(-2147483649.0), Limits<std::int32_t>::min());
  // float cannot hold 2^31 - 1: the largest float below 2^31 converts exactly, 2^31 saturates.
  EXPECT_EQ(convert<std::int32_t>(2147483520.0F), 2147483520);
  EXPECT_EQ(convert<std::int32_t>(2147483648.0F), Limits<std::int32_t>::max());
  EXPECT_EQ(convert<std::uint32_t>(4294967295.0), Limits<std::uint32_t>::max());
  EXPECT_EQ(convert<std::uint32_t>(4294967296.0), Limits<std::uint32_t>::max());
  EXPECT_EQ(convert<std::uint32_t>(4294967040.0F), 4294967040U);
  EXPECT_EQ(convert<std::uint32_t>(4294967296.0F), Limits<std::uint32_t>::max());
  EXPECT_EQ(convert<std::int64_t>(9223372036854774784.0), 9223372036854774784);  // the largest double below 2^63
  EXPECT_EQ(convert<std::int64_t>(9223372036854775808.0), Limits<std::int64_t>::max());
  EXPECT_EQ(convert<std::int64_t>(-1e19), Limits<std::int64_t>::min());
}

TEST(BlocksConvert, NanIsZeroAndInfinitiesSaturate) {
  EXPECT_EQ(convert<std::int8_t>(nan_value), 0);
  EXPECT_EQ(convert<std::uint32_t>(-nan_value), 0U);
  EXPECT_EQ(convert<std::int32_t>(Limits<float>::quiet_NaN()), 0);
  EXPECT_EQ(convert<std::int16_t>(infinity), 32767);
  EXPECT_EQ(convert<std::int16_t>(-infinity), -32768);
  EXPECT_EQ(convert<std::uint16_t>(-infinity), 0);
  EXPECT_EQ(convert<std::uint32_t>(Limits<float>::infinity()), Limits<std::uint32_t>::max());
  EXPECT_EQ(convert<std::int32_t>(-Limits<float>::infinity()), Limits<std::int32_t>::min());
}

TEST(BlocksConvert, IntegerToIntegerSaturates) {
  EXPECT_EQ(convert<std::int8_t>(std::int32_t{300}), 127);
  EXPECT_EQ(convert<std::int8_t>(std::int32_t{-300}), -128);
  EXPECT_EQ(convert<std::int8_t>(std::uint32_t{100}), 100);
  EXPECT_EQ(convert<std::int8_t>(std::uint8_t{200}), 127);
  EXPECT_EQ(convert<std::uint8_t>(std::int32_t{-1}), 0);
  EXPECT_EQ(convert<std::uint8_t>(std::int8_t{-128}), 0);
  EXPECT_EQ(convert<std::uint8_t>(std::uint32_t{256}), 255);
  EXPECT_EQ(convert<std::int16_t>(std::uint8_t{255}), 255);
  EXPECT_EQ(convert<std::uint16_t>(std::int32_t{70000}), 65535);
  EXPECT_EQ(convert<std::int32_t>(Limits<std::uint32_t>::max()), Limits<std::int32_t>::max());
  EXPECT_EQ(convert<std::uint32_t>(std::int8_t{-128}), 0U);
  EXPECT_EQ(convert<std::uint32_t>(Limits<std::int32_t>::max()), 2147483647U);
  EXPECT_EQ(convert<std::uint32_t>(Limits<std::int32_t>::min()), 0U);
  EXPECT_EQ(convert<std::int64_t>(Limits<std::uint32_t>::max()), 4294967295);
}

TEST(BlocksConvert, ToFloatingRoundsToNearest) {
  EXPECT_EQ(convert<float>(std::int32_t{16777217}), 16777216.0F);  // 2^24 + 1: the tie goes to the even 2^24
  EXPECT_EQ(convert<float>(std::int32_t{16777219}), 16777220.0F);
  EXPECT_EQ(convert<float>(Limits<std::uint32_t>::max()), 4294967296.0F);
  EXPECT_EQ(convert<double>(Limits<std::int32_t>::min()), -2147483648.0);
  EXPECT_EQ(convert<float>(0.1), 0.1F);
  EXPECT_EQ(convert<double>(0.1F), static_cast<double>(0.1F));
  EXPECT_TRUE(std::isnan(convert<float>(nan_value)));
  EXPECT_TRUE(std::signbit(convert<float>(-1e-320)));  // a double subnormal becomes -0.0F
  EXPECT_EQ(convert<float>(-1e-320), 0.0F);
}

TEST(BlocksConvert, DoubleBeyondFloatsRangeBecomesInfinityAsIeeeRoundsIt) {
  const auto largest = static_cast<double>(Limits<float>::max());
  const double threshold = largest + std::ldexp(1.0, 103);  // halfway between float's largest value and 2^128
  EXPECT_EQ(convert<float>(largest), Limits<float>::max());
  EXPECT_EQ(convert<float>(std::nextafter(threshold, 0.0)), Limits<float>::max());
  EXPECT_EQ(convert<float>(threshold), Limits<float>::infinity());
  EXPECT_EQ(convert<float>(-std::nextafter(threshold, 0.0)), Limits<float>::lowest());
  EXPECT_EQ(convert<float>(-threshold), -Limits<float>::infinity());
  EXPECT_EQ(convert<float>(1e300), Limits<float>::infinity());
  EXPECT_EQ(convert<float>(-infinity), -Limits<float>::infinity());
  // Inside the range: the hardware's own rounding.
  for (const double value : {largest, 3.0e38, -3.3e38, 1.0e-40}) {
    EXPECT_EQ(convert<float>(value), static_cast<float>(value)) << value;
  }
}

}  // namespace
}  // namespace duet::blocks
