#include "duet/blocks/arithmetic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace duet::blocks {
namespace {

template <typename T>
constexpr T max_of = std::numeric_limits<T>::max();
template <typename T>
constexpr T min_of = std::numeric_limits<T>::min();

// bool is rejected at compile time, not silently treated as 0 and 1.
template <typename T>
concept Addable = requires(T a) {
  add(a, a);
};
static_assert(Addable<float> && Addable<std::int8_t> && !Addable<bool>);

// Usable in constant expressions, as generated code may do for parameters.
static_assert(add<std::int8_t>(127, 1) == -128);
static_assert(multiply<std::uint16_t>(65535, 65535) == 1);
static_assert(divide(-7, 2) == -3);
static_assert(divide(min_of<std::int32_t>, -1) == min_of<std::int32_t>);
static_assert(divide<std::uint8_t>(5, 0) == 0);
static_assert(gain(0.5, 4.0) == 2.0);

TEST(BlocksArithmetic, AddWrapsAtBothEndsOfEveryIntegerType) {
  EXPECT_EQ(add<std::int8_t>(127, 1), -128);
  EXPECT_EQ(add<std::int8_t>(-128, -1), 127);
  EXPECT_EQ(add<std::uint8_t>(255, 1), 0);
  EXPECT_EQ(add<std::int16_t>(32767, 2), -32767);
  EXPECT_EQ(add<std::uint16_t>(65535, 65535), 65534);
  EXPECT_EQ(add(max_of<std::int32_t>, 1), min_of<std::int32_t>);
  EXPECT_EQ(add(min_of<std::int32_t>, min_of<std::int32_t>), 0);
  EXPECT_EQ(add<std::uint32_t>(max_of<std::uint32_t>, 2), 1U);
  EXPECT_EQ(add<std::int16_t>(100, -300), -200);
}

TEST(BlocksArithmetic, SubtractWraps) {
  EXPECT_EQ(subtract<std::uint8_t>(0, 1), 255);
  EXPECT_EQ(subtract<std::int8_t>(-128, 1), 127);
  EXPECT_EQ(subtract<std::int16_t>(-32768, 1), 32767);
  EXPECT_EQ(subtract(min_of<std::int32_t>, 1), max_of<std::int32_t>);
  EXPECT_EQ(subtract<std::uint32_t>(1, 2), max_of<std::uint32_t>);
  EXPECT_EQ(subtract<std::int8_t>(-5, -7), 2);
}

TEST(BlocksArithmetic, MultiplyWrapsWithoutPromotingToInt) {
  // 65535 * 65535 overflows int, where uint16 operands would be promoted by the plain operator.
  EXPECT_EQ(multiply<std::uint16_t>(65535, 65535), 1);
  EXPECT_EQ(multiply<std::int16_t>(256, 256), 0);
  EXPECT_EQ(multiply<std::int16_t>(-32768, -1), -32768);
  EXPECT_EQ(multiply<std::int8_t>(16, 9), -112);  // 144 - 256
  EXPECT_EQ(multiply<std::int8_t>(-128, -1), -128);
  EXPECT_EQ(multiply<std::uint8_t>(16, 16), 0);
  EXPECT_EQ(multiply<std::int32_t>(65536, 65536), 0);
  EXPECT_EQ(multiply<std::int32_t>(65537, 65537), 131073);  // 2^32 + 2^17 + 1
  EXPECT_EQ(multiply(min_of<std::int32_t>, -1), min_of<std::int32_t>);
  EXPECT_EQ(multiply<std::uint32_t>(max_of<std::uint32_t>, max_of<std::uint32_t>), 1U);
  EXPECT_EQ(multiply<std::int32_t>(-3, 7), -21);
}

TEST(BlocksArithmetic, NegateWrapsTheMostNegativeValueToItself) {
  EXPECT_EQ(negate<std::int8_t>(-128), -128);
  EXPECT_EQ(negate<std::int8_t>(127), -127);
  EXPECT_EQ(negate<std::int16_t>(5), -5);
  EXPECT_EQ(negate(min_of<std::int32_t>), min_of<std::int32_t>);
  EXPECT_EQ(negate<std::uint8_t>(1), 255);
  EXPECT_EQ(negate<std::uint32_t>(0), 0U);
  EXPECT_TRUE(std::signbit(negate(0.0F)));
  EXPECT_EQ(negate(2.5), -2.5);
}

TEST(BlocksArithmetic, IntegerDivisionTruncatesTowardZero) {
  EXPECT_EQ(divide<std::int32_t>(7, 2), 3);
  EXPECT_EQ(divide<std::int32_t>(-7, 2), -3);
  EXPECT_EQ(divide<std::int32_t>(7, -2), -3);
  EXPECT_EQ(divide<std::int32_t>(-7, -2), 3);
  EXPECT_EQ(divide<std::int8_t>(-128, 3), -42);
  EXPECT_EQ(divide<std::uint8_t>(200, 3), 66);
  EXPECT_EQ(divide<std::uint32_t>(max_of<std::uint32_t>, 2), 2147483647U);
}

TEST(BlocksArithmetic, IntegerDivisionByZeroGivesZeroAndMinByMinusOneWraps) {
  EXPECT_EQ(divide<std::int8_t>(100, 0), 0);
  EXPECT_EQ(divide<std::uint16_t>(1, 0), 0);
  EXPECT_EQ(divide(min_of<std::int32_t>, 0), 0);
  EXPECT_EQ(divide<std::uint32_t>(max_of<std::uint32_t>, 0), 0U);
  EXPECT_EQ(divide<std::int8_t>(-128, -1), -128);
  EXPECT_EQ(divide<std::int16_t>(-32768, -1), -32768);
  EXPECT_EQ(divide(min_of<std::int32_t>, -1), min_of<std::int32_t>);
  EXPECT_EQ(divide<std::int16_t>(1234, -1), -1234);
}

TEST(BlocksArithmetic, FloatingPointIsThePlainOperator) {
  const double a = 0.1;
  const double b = 0.2;
  EXPECT_EQ(add(a, b), a + b);
  EXPECT_EQ(subtract(a, b), a - b);
  EXPECT_EQ(multiply(a, b), a * b);
  EXPECT_EQ(divide(a, b), a / b);
  EXPECT_EQ(add(0.1F, 0.7F), 0.1F + 0.7F);
  EXPECT_EQ(divide(1.0F, 3.0F), 1.0F / 3.0F);
  EXPECT_EQ(divide(1.0F, 0.0F), std::numeric_limits<float>::infinity());
  EXPECT_EQ(divide(-1.0, 0.0), -std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(divide(0.0, 0.0)));
  EXPECT_TRUE(std::isnan(add(std::numeric_limits<float>::quiet_NaN(), 1.0F)));
}

TEST(BlocksArithmetic, GainMultipliesTheInputByTheGain) {
  EXPECT_EQ(gain(3.0F, 0.5F), 1.5F);
  EXPECT_EQ(gain<std::int8_t>(100, 2), -56);  // wraps like multiply
  EXPECT_EQ(gain<std::uint16_t>(1000, 3), 3000);
  EXPECT_EQ(gain(0.1, 0.3), 0.3 * 0.1);
}

}  // namespace
}  // namespace duet::blocks
