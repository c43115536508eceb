#include "duet/blocks/matrix_inverse.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "duet/blocks/matrix.hpp"

namespace duet::blocks {
namespace {

constexpr std::array<double, 4> inverse_2x2() {
  constexpr std::array<double, 4> a{2, 1, 1, 1};
  std::array<double, 4> inverse{};
  if (!matrix_inverse<double, 2>(a.data(), inverse.data())) return {};
  return inverse;
}
static_assert(inverse_2x2() == std::array<double, 4>{1, -1, -1, 2});

TEST(BlocksMatrixInverse, TwoByTwoByHand) {
  // [2 1; 1 1], determinant 1. Column 0: pivot 2 (row 0), row 0 / 2: m = [1 0.5], w = [0.5 0];
  // row 1 - 1 * row 0: m = [0 0.5], w = [-0.5 1]. Column 1: pivot 0.5, row 1 / 0.5: w = [-1 2];
  // row 0 - 0.5 * row 1: w = [0.5 + 0.5, 0 - 1] = [1 -1].
  const std::array<float, 4> a{2, 1, 1, 1};
  std::array<float, 4> inverse{};
  ASSERT_TRUE((matrix_inverse<float, 2>(a.data(), inverse.data())));
  EXPECT_EQ(inverse, (std::array<float, 4>{1, -1, -1, 2}));
}

TEST(BlocksMatrixInverse, PivotsOnTheLargestMagnitude) {
  // A zero on the diagonal needs a row swap: a permutation and a scaling.
  const std::array<double, 9> permutation{0, 1, 0, 1, 0, 0, 0, 0, 2};
  std::array<double, 9> inverse{};
  ASSERT_TRUE((matrix_inverse<double, 3>(permutation.data(), inverse.data())));
  EXPECT_EQ(inverse, (std::array<double, 9>{0, 1, 0, 1, 0, 0, 0, 0, 0.5}));
  // [1e-20 1; 1 1]: the inverse is [1 -1; -1 1e-20] / (1e-20 - 1), about [-1 1; 1 -1e-20]. Pivoting on 1e-20 would
  // compute w[0][0] = 1e20 - 1e20 * 1 = 0; with the pivot 1 from row 1 it comes out right.
  const std::array<double, 4> tiny_pivot{1e-20, 1, 1, 1};
  std::array<double, 4> result{};
  ASSERT_TRUE((matrix_inverse<double, 2>(tiny_pivot.data(), result.data())));
  EXPECT_DOUBLE_EQ(result[0], -1.0);
  EXPECT_DOUBLE_EQ(result[1], 1.0);
  EXPECT_DOUBLE_EQ(result[2], 1.0);
  EXPECT_NEAR(result[3], -1e-20, 1e-35);
}

TEST(BlocksMatrixInverse, SingularMatricesLeaveTheResultUntouched) {
  // [1 2; 2 4]: pivot 2 (row 1), then row 0 becomes [1 2] - 1 * [1 2] = [0 0]: no pivot for column 1.
  const std::array<double, 4> rank_one{1, 2, 2, 4};
  std::array<double, 4> inverse{7, 7, 7, 7};
  EXPECT_FALSE((matrix_inverse<double, 2>(rank_one.data(), inverse.data())));
  EXPECT_EQ(inverse, (std::array<double, 4>{7, 7, 7, 7}));
  const std::array<float, 1> zero{0.0F};
  std::array<float, 1> scalar{7.0F};
  EXPECT_FALSE((matrix_inverse<float, 1>(zero.data(), scalar.data())));
  EXPECT_EQ(scalar[0], 7.0F);
  const std::array<float, 1> nan_value{std::numeric_limits<float>::quiet_NaN()};
  EXPECT_FALSE((matrix_inverse<float, 1>(nan_value.data(), scalar.data())));
  EXPECT_EQ(scalar[0], 7.0F);
}

TEST(BlocksMatrixInverse, InPlaceAndOneByOne) {
  std::array<double, 4> a{2, 1, 1, 1};
  ASSERT_TRUE((matrix_inverse<double, 2>(a.data(), a.data())));
  EXPECT_EQ(a, (std::array<double, 4>{1, -1, -1, 2}));
  const std::array<float, 1> four{4.0F};
  std::array<float, 1> quarter{};
  ASSERT_TRUE((matrix_inverse<float, 1>(four.data(), quarter.data())));
  EXPECT_EQ(quarter[0], 0.25F);
}

TEST(BlocksMatrixInverse, TimesTheMatrixIsTheIdentity) {
  const std::array<float, 9> a{4.0F, -2.0F, 1.0F, 3.0F, 6.0F, -4.0F, 2.0F, 1.0F, 8.0F};
  std::array<float, 9> inverse{};
  ASSERT_TRUE((matrix_inverse<float, 3>(a.data(), inverse.data())));
  std::array<float, 9> product{};
  matrix_multiply(a.data(), inverse.data(), product.data(), 3, 3, 3);
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) EXPECT_NEAR(product[i * 3 + j], i == j ? 1.0F : 0.0F, 1e-6F) << i << j;
  }
}

}  // namespace
}  // namespace duet::blocks
