#include "duet/blocks/bytes.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace duet::blocks {
namespace {

constexpr std::int16_t unpacked_big_endian() {
  constexpr std::array<std::uint8_t, 2> bytes{0x12, 0x34};
  return unpack<std::int16_t>(bytes.data(), Endian::big);
}
static_assert(unpacked_big_endian() == 0x1234);

template <typename T>
std::array<std::uint8_t, sizeof(T)> packed(T value, Endian endian) {
  std::array<std::uint8_t, sizeof(T)> bytes{};
  pack(value, endian, bytes.data());
  return bytes;
}

TEST(BlocksBytes, Int16BigEndian) {
  const std::array<std::uint8_t, 2> positive{0x12, 0x34};
  EXPECT_EQ(unpack<std::int16_t>(positive.data(), Endian::big), 0x1234);
  EXPECT_EQ(unpack<std::int16_t>(positive.data(), Endian::little), 0x3412);
  // 0xFF38 = 65336 = 65536 - 200: two's complement -200.
  const std::array<std::uint8_t, 2> negative{0xFF, 0x38};
  EXPECT_EQ(unpack<std::int16_t>(negative.data(), Endian::big), -200);
  EXPECT_EQ(unpack<std::uint16_t>(negative.data(), Endian::big), 0xFF38);
  EXPECT_EQ(packed<std::int16_t>(-200, Endian::big), (std::array<std::uint8_t, 2>{0xFF, 0x38}));
  EXPECT_EQ(packed<std::int16_t>(-200, Endian::little), (std::array<std::uint8_t, 2>{0x38, 0xFF}));
}

TEST(BlocksBytes, WiderIntegersInBothOrders) {
  EXPECT_EQ(packed<std::uint32_t>(0x01020304U, Endian::big), (std::array<std::uint8_t, 4>{1, 2, 3, 4}));
  EXPECT_EQ(packed<std::uint32_t>(0x01020304U, Endian::little), (std::array<std::uint8_t, 4>{4, 3, 2, 1}));
  // -2 = 0xFFFFFFFE.
  EXPECT_EQ(packed<std::int32_t>(-2, Endian::little), (std::array<std::uint8_t, 4>{0xFE, 0xFF, 0xFF, 0xFF}));
  EXPECT_EQ(packed<std::int8_t>(-1, Endian::big), (std::array<std::uint8_t, 1>{0xFF}));
}

TEST(BlocksBytes, FloatingPointIsItsIeeeBits) {
  // 1.0f = sign 0, exponent 127 (0x7F << 23), fraction 0: 0x3F800000.
  EXPECT_EQ(packed(1.0F, Endian::little), (std::array<std::uint8_t, 4>{0x00, 0x00, 0x80, 0x3F}));
  EXPECT_EQ(packed(1.0F, Endian::big), (std::array<std::uint8_t, 4>{0x3F, 0x80, 0x00, 0x00}));
  // -2.0 = sign 1, exponent 1024 (0x400 << 52): 0xC000000000000000.
  EXPECT_EQ(packed(-2.0, Endian::big), (std::array<std::uint8_t, 8>{0xC0, 0, 0, 0, 0, 0, 0, 0}));
  const std::array<std::uint8_t, 4> minus_zero{0x80, 0, 0, 0};
  EXPECT_TRUE(std::signbit(unpack<float>(minus_zero.data(), Endian::big)));
}

TEST(BlocksBytes, BoolIsOneByte) {
  EXPECT_EQ(packed(true, Endian::big), (std::array<std::uint8_t, 1>{1}));
  EXPECT_EQ(packed(false, Endian::little), (std::array<std::uint8_t, 1>{0}));
  const std::array<std::uint8_t, 1> other{0x80};
  EXPECT_TRUE(unpack<bool>(other.data(), Endian::little));
}

template <typename T>
void expect_round_trip(T value) {
  for (const Endian endian : {Endian::little, Endian::big}) {
    const auto bytes = packed(value, endian);
    const T back = unpack<T>(bytes.data(), endian);
    if constexpr (std::is_floating_point_v<T>) {
      if (std::isnan(value)) {
        EXPECT_EQ(packed(back, endian), bytes);  // the very same NaN, payload and sign included
        continue;
      }
      EXPECT_EQ(std::signbit(back), std::signbit(value));
    }
    EXPECT_EQ(back, value);
  }
}

template <typename T>
void expect_round_trips_of_limits() {
  expect_round_trip<T>(std::numeric_limits<T>::lowest());
  expect_round_trip<T>(std::numeric_limits<T>::max());
  expect_round_trip<T>(T{0});
  expect_round_trip<T>(T{1});
}

TEST(BlocksBytes, EveryTypeRoundTrips) {
  expect_round_trips_of_limits<std::int8_t>();
  expect_round_trips_of_limits<std::int16_t>();
  expect_round_trips_of_limits<std::int32_t>();
  expect_round_trips_of_limits<std::uint8_t>();
  expect_round_trips_of_limits<std::uint16_t>();
  expect_round_trips_of_limits<std::uint32_t>();
  expect_round_trips_of_limits<float>();
  expect_round_trips_of_limits<double>();
  expect_round_trip<std::int16_t>(-200);
  expect_round_trip<std::int32_t>(-123456789);
  expect_round_trip(true);
  expect_round_trip(false);
  for (const float value : {-0.0F, 0.1F, std::numeric_limits<float>::denorm_min(),
                            -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
    expect_round_trip(value);
  }
  for (const double value : {-0.0, 0.1, std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::quiet_NaN()}) {
    expect_round_trip(value);
  }
}

}  // namespace
}  // namespace duet::blocks
