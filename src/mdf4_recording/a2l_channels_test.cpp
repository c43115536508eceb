// A2L variables as MDF channels: every data type's exact stored type, the conversions MDF gets and those it does not
// (said in the comment), and raw bytes as typed values.
#include "duet/mdf4_recording/a2l_channels.hpp"

#include <gtest/gtest.h>

#include <bit>

namespace duet::mdf4_recording {
namespace {

using xcp::host::DataType;
using xcp::host::Variable;

TEST(A2lChannels, EveryA2lDataTypeHasItsExactMdfType) {
  EXPECT_EQ(value_type(DataType::uint8), mdf4::ValueType::u8);
  EXPECT_EQ(value_type(DataType::int8), mdf4::ValueType::i8);
  EXPECT_EQ(value_type(DataType::uint16), mdf4::ValueType::u16);
  EXPECT_EQ(value_type(DataType::int16), mdf4::ValueType::i16);
  EXPECT_EQ(value_type(DataType::uint32), mdf4::ValueType::u32);
  EXPECT_EQ(value_type(DataType::int32), mdf4::ValueType::i32);
  EXPECT_EQ(value_type(DataType::uint64), mdf4::ValueType::u64);
  EXPECT_EQ(value_type(DataType::int64), mdf4::ValueType::i64);
  EXPECT_EQ(value_type(DataType::float32), mdf4::ValueType::f32);
  EXPECT_EQ(value_type(DataType::float64), mdf4::ValueType::f64);
}

TEST(A2lChannels, ALinearConversionIsWrittenAndAnIdentityIsNone) {
  const Variable coolant{.name = "coolant",
                         .description = "coolant temperature",
                         .type = DataType::uint8,
                         .unit = "degC",
                         .conversion = {0.5, -40}};
  const mdf4::ChannelSpec spec = channel(coolant);
  EXPECT_EQ(spec.name, "coolant");
  EXPECT_EQ(spec.type, mdf4::ValueType::u8);
  EXPECT_EQ(spec.unit, "degC");
  EXPECT_EQ(spec.comment, "coolant temperature");
  ASSERT_TRUE(spec.conversion);
  EXPECT_EQ(spec.conversion->factor, 0.5);
  EXPECT_EQ(spec.conversion->offset, -40);
  EXPECT_EQ(spec.elements, 1U);

  const Variable plain{.name = "theta", .description = "tilt", .type = DataType::float32, .count = 3};
  EXPECT_FALSE(channel(plain).conversion);
  EXPECT_EQ(channel(plain).elements, 3U);
}

TEST(A2lChannels, OtherConversionsAreStoredRawAndTheCommentSaysSo) {
  const Variable gear{.name = "gear",
                      .description = "the gear engaged",
                      .type = DataType::uint8,
                      .labels = {{0, "neutral"}, {1, "first"}, {2.5, "half"}}};
  EXPECT_FALSE(channel(gear).conversion);
  EXPECT_EQ(channel(gear).comment, "the gear engaged (raw values, named by the A2L: 0 neutral, 1 first, 2.5 half)");

  const Variable pedal{.name = "pedal", .type = DataType::uint16, .unapplied_conversion = "TAB_INTP"};
  EXPECT_FALSE(channel(pedal).conversion);
  EXPECT_EQ(channel(pedal).comment, "raw values: the A2L's TAB_INTP conversion is not written");
}

TEST(A2lChannels, RawBytesBecomeValuesOfTheirExactType) {
  std::vector<mdf4::Value> values;
  append_raw_values({.type = DataType::int16, .count = 2}, std::vector<std::uint8_t>{0xFE, 0xFF, 0x34, 0x12}, values);
  append_raw_values({.type = DataType::uint8}, std::vector<std::uint8_t>{0xFF}, values);
  append_raw_values({.type = DataType::int8}, std::vector<std::uint8_t>{0x80}, values);
  append_raw_values({.type = DataType::uint16}, std::vector<std::uint8_t>{0xFF, 0xFF}, values);
  append_raw_values({.type = DataType::uint32}, std::vector<std::uint8_t>{1, 0, 0, 0x80}, values);
  append_raw_values({.type = DataType::int32}, std::vector<std::uint8_t>{0xFF, 0xFF, 0xFF, 0xFF}, values);
  append_raw_values({.type = DataType::uint64}, std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0x80}, values);
  append_raw_values({.type = DataType::int64},
                    std::vector<std::uint8_t>{0xFE, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}, values);
  append_raw_values({.type = DataType::float32}, std::vector<std::uint8_t>{0x00, 0x00, 0xC0, 0x3F}, values);
  append_raw_values({.type = DataType::float64}, std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0xF8, 0xBF}, values);
  ASSERT_EQ(values.size(), 11U);
  EXPECT_EQ(values[0], mdf4::Value{std::int16_t{-2}});
  EXPECT_EQ(values[1], mdf4::Value{std::int16_t{0x1234}});
  EXPECT_EQ(values[2], mdf4::Value{std::uint8_t{255}});
  EXPECT_EQ(values[3], mdf4::Value{std::int8_t{-128}});
  EXPECT_EQ(values[4], mdf4::Value{std::uint16_t{65535}});
  EXPECT_EQ(values[5], mdf4::Value{std::uint32_t{0x80000001}});
  EXPECT_EQ(values[6], mdf4::Value{std::int32_t{-1}});
  EXPECT_EQ(values[7], mdf4::Value{std::uint64_t{1} << 63});
  EXPECT_EQ(values[8], mdf4::Value{std::int64_t{-2}});
  EXPECT_EQ(values[9], mdf4::Value{1.5f});
  EXPECT_EQ(values[10], mdf4::Value{-1.5});
}

}  // namespace
}  // namespace duet::mdf4_recording
