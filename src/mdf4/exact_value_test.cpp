// A double in a channel's type only when the type holds it exactly: the edges of each integer type (64 bits
// included, where max() + 1 rounds to the first value past the type), booleans, floats, NaN.
#include "duet/mdf4/exact_value.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace duet::mdf4 {
namespace {

TEST(ExactValue, IntegersAreWholeNumbersWithinTheirRange) {
  EXPECT_EQ(exactly(ValueType::u8, 255), Value{std::uint8_t{255}});
  EXPECT_FALSE(exactly(ValueType::u8, 256));
  EXPECT_FALSE(exactly(ValueType::u8, -1));
  EXPECT_FALSE(exactly(ValueType::u8, 1.5));
  EXPECT_EQ(exactly(ValueType::i8, -128), Value{std::int8_t{-128}});
  EXPECT_FALSE(exactly(ValueType::i8, -129));
  EXPECT_EQ(exactly(ValueType::u32, 4294967295.0), Value{std::uint32_t{4294967295U}});
  EXPECT_EQ(exactly(ValueType::i32, -2147483648.0), Value{std::int32_t{-2147483647 - 1}});
  EXPECT_FALSE(exactly(ValueType::i64, 9223372036854775808.0));  // 2^63
  EXPECT_EQ(exactly(ValueType::i64, -9223372036854775808.0), Value{std::numeric_limits<std::int64_t>::min()});
  EXPECT_FALSE(exactly(ValueType::u64, 18446744073709551616.0));  // 2^64
  EXPECT_FALSE(exactly(ValueType::u16, std::nan("")));
  EXPECT_FALSE(exactly(ValueType::i16, std::numeric_limits<double>::infinity()));
}

TEST(ExactValue, BooleansFloatsAndDoubles) {
  EXPECT_EQ(exactly(ValueType::boolean, 1), Value{true});
  EXPECT_EQ(exactly(ValueType::boolean, 0), Value{false});
  EXPECT_FALSE(exactly(ValueType::boolean, 2));
  EXPECT_EQ(exactly(ValueType::f32, 0.5), Value{0.5F});
  EXPECT_FALSE(exactly(ValueType::f32, 0.1));  // no float is 0.1 exactly
  EXPECT_FALSE(exactly(ValueType::f32, 1e39));
  EXPECT_EQ(exactly(ValueType::f32, -std::numeric_limits<double>::infinity()),
            Value{-std::numeric_limits<float>::infinity()});
  EXPECT_TRUE(std::isnan(std::get<float>(*exactly(ValueType::f32, std::nan("")))));
  EXPECT_EQ(exactly(ValueType::f64, 0.1), Value{0.1});
}

}  // namespace
}  // namespace duet::mdf4
