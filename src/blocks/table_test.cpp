#include "duet/blocks/table.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <limits>
#include <span>

namespace duet::blocks {
namespace {

constexpr std::array<double, 3> table{10.0, 20.0, 30.0};

static_assert(element_at(std::span<const double>(table), 1) == 20.0);
static_assert(element_at(std::span<const double>(table), -2.5F) == 10.0);
static_assert(element_at(std::span<const double>(table), 7U) == 30.0);

TEST(BlocksElementAt, IntegerIndexesAreClampedToTheTable) {
  const std::span<const double> values(table);
  EXPECT_EQ(element_at(values, -3), 10.0);
  EXPECT_EQ(element_at(values, 0), 10.0);
  EXPECT_EQ(element_at(values, 1), 20.0);
  EXPECT_EQ(element_at(values, 2), 30.0);
  EXPECT_EQ(element_at(values, 3), 30.0);
  EXPECT_EQ(element_at(values, std::numeric_limits<std::int32_t>::max()), 30.0);
  EXPECT_EQ(element_at(values, std::numeric_limits<std::int32_t>::min()), 10.0);
  EXPECT_EQ(element_at(values, std::numeric_limits<std::uint32_t>::max()), 30.0);
  EXPECT_EQ(element_at(values, std::int8_t{-128}), 10.0);
  EXPECT_EQ(element_at(values, std::uint8_t{1}), 20.0);
  EXPECT_EQ(element_at(values, true), 20.0);
}

TEST(BlocksElementAt, FloatingIndexesTruncateTowardZero) {
  const std::span<const double> values(table);
  EXPECT_EQ(element_at(values, -0.9F), 10.0);
  EXPECT_EQ(element_at(values, -1.5), 10.0);
  EXPECT_EQ(element_at(values, 0.99), 10.0);
  EXPECT_EQ(element_at(values, 1.9F), 20.0);
  EXPECT_EQ(element_at(values, 2.7), 30.0);
  EXPECT_EQ(element_at(values, 1e30), 30.0);
  EXPECT_EQ(element_at(values, -1e30F), 10.0);
  // Beyond std::int64_t, where a 32-bit std::size_t must not cut the position down into the table.
  EXPECT_EQ(element_at(values, 4294967297.0), 30.0);
}

TEST(BlocksElementAt, NanReadsTheFirstElementAndInfinitiesTheEnds) {
  const std::span<const double> values(table);
  EXPECT_EQ(element_at(values, std::numeric_limits<float>::quiet_NaN()), 10.0);
  EXPECT_EQ(element_at(values, std::numeric_limits<double>::infinity()), 30.0);
  EXPECT_EQ(element_at(values, -std::numeric_limits<double>::infinity()), 10.0);
}

TEST(BlocksElementAt, OtherElementTypesAndTheEmptyTable) {
  const std::array<std::int16_t, 4> words{-1, -2, -3, -4};
  EXPECT_EQ(element_at(std::span<const std::int16_t>(words), 3.5F), -4);
  const std::array<bool, 2> flags{false, true};
  EXPECT_TRUE(element_at(std::span<const bool>(flags), 9));
  EXPECT_EQ(element_at(std::span<const float>(), 0), 0.0F);  // precondition broken: T{}, not a read
}

}  // namespace
}  // namespace duet::blocks
