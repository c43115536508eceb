#include "duet/blocks/average.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace duet::blocks {
namespace {

static_assert(std::is_aggregate_v<MovingAverage<float, 4>>);

constexpr double mean_of_three() {
  const double u[] = {1.0, 2.0, 6.0};
  return mean(u, 3);
}
static_assert(mean_of_three() == 3.0);

TEST(BlocksMean, SumsLeftToRightThenDivides) {
  const std::array<double, 4> u{1.0, -2.0, 0.5, 4.5};
  EXPECT_EQ(mean(u.data(), u.size()), 1.0);  // 4 / 4
  EXPECT_EQ(mean(u.data(), 1), 1.0);
  EXPECT_EQ(mean<double>(nullptr, 0), 0.0);
  // (1 + 1e8) - 1e8 = 0 in float (spacing 8 at 1e8); right to left (-1e8 + 1e8) + 1 = 1 would give 1/3.
  const std::array<float, 3> order{1.0F, 1e8F, -1e8F};
  EXPECT_EQ(mean(order.data(), order.size()), 0.0F);
  // Divided once at the end: 0.1 + 0.2 + 0.3 then / 3, not a sum of thirds.
  const std::array<double, 3> tenths{0.1, 0.2, 0.3};
  EXPECT_EQ(mean(tenths.data(), tenths.size()), ((0.1 + 0.2) + 0.3) / 3.0);
}

TEST(BlocksMovingAverage, MeanOfTheLastNInputsIncludingTheCurrentOne) {
  // N = 3 from zeros: inputs 3, 6, 9, 12, 0
  //   (0 + 0 + 3) / 3 = 1;  (0 + 3 + 6) / 3 = 3;  (3 + 6 + 9) / 3 = 6;  (6 + 9 + 12) / 3 = 9;  (9 + 12 + 0) / 3 = 7
  MovingAverage<double, 3> average{};
  std::vector<double> outputs;
  for (const double u : {3.0, 6.0, 9.0, 12.0, 0.0}) {
    outputs.push_back(average.output(u));
    average.update(u);
  }
  EXPECT_EQ(outputs, (std::vector<double>{1.0, 3.0, 6.0, 9.0, 7.0}));
  // Five inputs went to slots 0, 1, 2, 0, 1: the ring holds 12, 0, 9 and the oldest slot is 2.
  EXPECT_EQ(average.next, 2U);
  EXPECT_EQ(average.window[0], 12.0);
  EXPECT_EQ(average.window[1], 0.0);
  EXPECT_EQ(average.window[2], 9.0);
}

TEST(BlocksMovingAverage, StartsFromTheInitialWindow) {
  // Slots after next = 0 hold the previous inputs oldest first: 2 (slot 1), 4 (slot 2), 6 (slot 3); slot 0 is unused.
  MovingAverage<float, 4> average{{100.0F, 2.0F, 4.0F, 6.0F}, 0};
  EXPECT_EQ(average.output(8.0F), 5.0F);  // (2 + 4 + 6 + 8) / 4
  average.update(8.0F);
  EXPECT_EQ(average.output(0.0F), 4.5F);  // (4 + 6 + 8 + 0) / 4
  // An out-of-range next is taken modulo N: 6 % 4 = 2, so the previous inputs are slots 3, 0, 1: 6, 8, 2.
  MovingAverage<float, 4> wrapped{{0.0F, 2.0F, 4.0F, 6.0F}, 6};
  wrapped.window[0] = 8.0F;
  EXPECT_EQ(wrapped.output(4.0F), 5.0F);  // (6 + 8 + 2 + 4) / 4
  wrapped.update(4.0F);
  EXPECT_EQ(wrapped.window[2], 4.0F);
  EXPECT_EQ(wrapped.next, 3U);
}

TEST(BlocksMovingAverage, SumsOldestToNewest) {
  // Oldest to newest in float: (1 + 1e8) - 1e8 = 0, then + 0 = 0, / 3. Newest first would give 1 / 3.
  MovingAverage<float, 3> average{};
  average.update(1.0F);
  average.update(1e8F);
  EXPECT_EQ(average.output(-1e8F), 0.0F);
}

TEST(BlocksMovingAverage, WindowOfOneIsTheInput) {
  MovingAverage<double, 1> average{};
  EXPECT_EQ(average.output(0.1), 0.1);
  average.update(0.1);
  EXPECT_EQ(average.output(-7.25), -7.25);
  EXPECT_EQ(average.next, 0U);
}

}  // namespace
}  // namespace duet::blocks
