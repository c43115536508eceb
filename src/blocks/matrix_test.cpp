#include "duet/blocks/matrix.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace duet::blocks {
namespace {

constexpr std::array<double, 4> product_2x3_by_3x2() {
  constexpr std::array<double, 6> a{1, 2, 3, 4, 5, 6};
  constexpr std::array<double, 6> b{7, 8, 9, 10, 11, 12};
  std::array<double, 4> y{};
  matrix_multiply(a.data(), b.data(), y.data(), 2, 3, 2);
  return y;
}
static_assert(product_2x3_by_3x2() == std::array<double, 4>{58, 64, 139, 154});

TEST(BlocksMatrixMultiply, TwoByThreeTimesThreeByTwo) {
  // [1 2 3; 4 5 6] * [7 8; 9 10; 11 12] = [58 64; 139 154]
  const std::array<std::int16_t, 6> a{1, 2, 3, 4, 5, 6};
  const std::array<std::int16_t, 6> b{7, 8, 9, 10, 11, 12};
  std::array<std::int16_t, 4> y{};
  matrix_multiply(a.data(), b.data(), y.data(), 2, 3, 2);
  EXPECT_EQ(y, (std::array<std::int16_t, 4>{58, 64, 139, 154}));
  EXPECT_EQ(product_2x3_by_3x2(), (std::array<double, 4>{58, 64, 139, 154}));
}

TEST(BlocksMatrixMultiply, ThreeByTwoTimesTwoByThreeIsRowMajor) {
  const std::array<float, 6> a{1, 2, 3, 4, 5, 6};   // 3 x 2
  const std::array<float, 6> b{1, 0, -1, 0, 1, 2};  // 2 x 3
  std::array<float, 9> y{};
  matrix_multiply(a.data(), b.data(), y.data(), 3, 2, 3);
  EXPECT_EQ(y, (std::array<float, 9>{1, 2, 3, 3, 4, 5, 5, 6, 7}));
}

TEST(BlocksMatrixMultiply, SumsInIncreasingInnerIndexFromZero) {
  // 1 + 1e8 rounds to 1e8 in float: k = 0, 1, 2 gives (1 + 1e8) - 1e8 = 0, the other way round (-1e8 + 1e8) + 1 = 1.
  const std::array<float, 3> row{1.0F, 1e8F, -1e8F};
  const std::array<float, 3> column{1.0F, 1.0F, 1.0F};
  std::array<float, 1> y{-5.0F};
  matrix_multiply(row.data(), column.data(), y.data(), 1, 3, 1);
  EXPECT_EQ(y[0], 0.0F);
}

TEST(BlocksMatrixMultiply, IntegerProductsAndSumsWrap) {
  const std::array<std::int8_t, 2> row{100, 100};
  const std::array<std::int8_t, 2> column{2, 1};
  std::array<std::int8_t, 1> y{};
  matrix_multiply(row.data(), column.data(), y.data(), 1, 2, 1);
  EXPECT_EQ(y[0], 44);  // 200 wraps to -56, then -56 + 100
}

TEST(BlocksMatrixMultiply, EmptyInnerDimensionGivesZeros) {
  std::array<double, 4> y{1, 2, 3, 4};
  matrix_multiply<double>(nullptr, nullptr, y.data(), 2, 0, 2);
  EXPECT_EQ(y, (std::array<double, 4>{0, 0, 0, 0}));
}

TEST(BlocksMatrixTranspose, TwoByThreeBecomesThreeByTwo) {
  // [1 2 3; 4 5 6]^T = [1 4; 2 5; 3 6]
  const std::array<double, 6> a{1, 2, 3, 4, 5, 6};
  std::array<double, 6> y{};
  matrix_transpose(a.data(), y.data(), 2, 3);
  EXPECT_EQ(y, (std::array<double, 6>{1, 4, 2, 5, 3, 6}));
  const std::array<bool, 2> column{true, false};
  std::array<bool, 2> row{};
  matrix_transpose(column.data(), row.data(), 2, 1);
  EXPECT_EQ(row, column);  // a vector's transpose has the same elements in the same order
}

}  // namespace
}  // namespace duet::blocks
