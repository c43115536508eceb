// Model signals' types as MDF types, and values held as doubles back in their exact types, or refused.
#include "duet/mdf4_recording/typed_values.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace duet::mdf4_recording {
namespace {

using mdf4::ValueType;
using model::DataType;

TEST(TypedValues, EveryModelTypeHasItsExactMdfType) {
  EXPECT_EQ(value_type(DataType::float64), ValueType::f64);
  EXPECT_EQ(value_type(DataType::float32), ValueType::f32);
  EXPECT_EQ(value_type(DataType::int8), ValueType::i8);
  EXPECT_EQ(value_type(DataType::int16), ValueType::i16);
  EXPECT_EQ(value_type(DataType::int32), ValueType::i32);
  EXPECT_EQ(value_type(DataType::uint8), ValueType::u8);
  EXPECT_EQ(value_type(DataType::uint16), ValueType::u16);
  EXPECT_EQ(value_type(DataType::uint32), ValueType::u32);
  EXPECT_EQ(value_type(DataType::boolean), ValueType::boolean);
}

TEST(TypedValues, ADoubleComesBackInItsType) {
  EXPECT_EQ(typed_value(1, ValueType::boolean).value(), mdf4::Value{true});
  EXPECT_EQ(typed_value(0, ValueType::boolean).value(), mdf4::Value{false});
  EXPECT_EQ(typed_value(255, ValueType::u8).value(), mdf4::Value{std::uint8_t{255}});
  EXPECT_EQ(typed_value(65535, ValueType::u16).value(), mdf4::Value{std::uint16_t{65535}});
  EXPECT_EQ(typed_value(4294967295.0, ValueType::u32).value(), mdf4::Value{std::uint32_t{4294967295U}});
  EXPECT_EQ(typed_value(9007199254740992.0, ValueType::u64).value(), mdf4::Value{std::uint64_t{9007199254740992U}});
  EXPECT_EQ(typed_value(-128, ValueType::i8).value(), mdf4::Value{std::int8_t{-128}});
  EXPECT_EQ(typed_value(-32768, ValueType::i16).value(), mdf4::Value{std::int16_t{-32768}});
  EXPECT_EQ(typed_value(-2147483648.0, ValueType::i32).value(), mdf4::Value{std::int32_t{-2147483647 - 1}});
  EXPECT_EQ(typed_value(-9223372036854775808.0, ValueType::i64).value(),
            mdf4::Value{std::numeric_limits<std::int64_t>::min()});
  EXPECT_EQ(typed_value(0.1, ValueType::f32).value(), mdf4::Value{0.1F});
  EXPECT_EQ(typed_value(0.1, ValueType::f64).value(), mdf4::Value{0.1});
  EXPECT_TRUE(std::isnan(std::get<float>(typed_value(NAN, ValueType::f32).value())));
  EXPECT_EQ(typed_value(-HUGE_VAL, ValueType::f64).value(), mdf4::Value{-HUGE_VAL});
}

TEST(TypedValues, AValueTheTypeDoesNotHoldIsRefused) {
  EXPECT_EQ(typed_value(0.5, ValueType::i16).error(), "0.5 is no i16 value");
  EXPECT_EQ(typed_value(256, ValueType::u8).error(), "256 is no u8 value");
  EXPECT_EQ(typed_value(-1, ValueType::u32).error(), "-1 is no u32 value");
  EXPECT_EQ(typed_value(2, ValueType::boolean).error(), "2 is no boolean value");
  EXPECT_EQ(typed_value(18446744073709551616.0, ValueType::u64).error(), "18446744073709551616 is no u64 value");
  EXPECT_EQ(typed_value(9223372036854775808.0, ValueType::i64).error(), "9223372036854775808 is no i64 value");
  EXPECT_FALSE(typed_value(NAN, ValueType::i8).ok());
  EXPECT_FALSE(typed_value(1e39, ValueType::f32).ok());
}

}  // namespace
}  // namespace duet::mdf4_recording
