#include "duet/blocks/transfer_function.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace duet::blocks {
namespace {

static_assert(std::is_aggregate_v<DiscreteTransferFunction<float, 2>>);
static_assert(sizeof(DiscreteTransferFunction<double, 3>) == 3 * sizeof(double));

template <typename T, std::size_t N>
std::vector<T> step_response(DiscreteTransferFunction<T, N> filter, const std::array<T, N + 1>& numerator,
                             const std::array<T, N + 1>& denominator, int steps) {
  std::vector<T> outputs;
  for (int k = 0; k < steps; ++k) {
    outputs.push_back(filter.output(T{1}, numerator.data(), denominator.data()));
    filter.update(T{1}, numerator.data(), denominator.data());
  }
  return outputs;
}

constexpr double first_order_after_three_steps() {
  DiscreteTransferFunction<double, 1> filter{};
  const double numerator[] = {0.5, 0.0};
  const double denominator[] = {1.0, -0.5};
  for (int k = 0; k < 2; ++k) filter.update(1.0, numerator, denominator);
  return filter.output(1.0, numerator, denominator);
}
static_assert(first_order_after_three_steps() == 0.875);

TEST(BlocksDiscreteTransferFunction, FirstOrderLowpass) {
  // y(k) = 0.5 y(k-1) + 0.5 u(k): H = 0.5 / (1 - 0.5 z^-1), b = {0.5, 0}, a = {1, -0.5}. Unit step from rest:
  //   y0 = 0.5 * 1 + 0 = 0.5        state = 0 * 1 - (-0.5) * 0.5 = 0.25
  //   y1 = 0.5 + 0.25 = 0.75        state = 0.375
  //   y2 = 0.5 + 0.375 = 0.875      state = 0.4375
  EXPECT_EQ((step_response<double, 1>({}, {0.5, 0.0}, {1.0, -0.5}, 3)), (std::vector<double>{0.5, 0.75, 0.875}));
  EXPECT_EQ((step_response<float, 1>({}, {0.5F, 0.0F}, {1.0F, -0.5F}, 3)), (std::vector<float>{0.5F, 0.75F, 0.875F}));
}

TEST(BlocksDiscreteTransferFunction, DividesByTheLeadingDenominatorCoefficient) {
  // The same filter as 1 / (2 - z^-1): b' = {0.5, 0}, a' = {1, -0.5}.
  EXPECT_EQ((step_response<double, 1>({}, {1.0, 0.0}, {2.0, -1.0}, 3)), (std::vector<double>{0.5, 0.75, 0.875}));
}

TEST(BlocksDiscreteTransferFunction, SecondOrderByHand) {
  // H = (1 + 0.5 z^-1 + 0.25 z^-2) / (1 - 0.5 z^-1 + 0.25 z^-2):
  //   y(k) = u(k) + 0.5 u(k-1) + 0.25 u(k-2) + 0.5 y(k-1) - 0.25 y(k-2). Unit step from rest:
  //   y0 = 1
  //   y1 = 1 + 0.5 + 0.5 * 1 = 2
  //   y2 = 1.75 + 0.5 * 2 - 0.25 * 1 = 2.5
  //   y3 = 1.75 + 0.5 * 2.5 - 0.25 * 2 = 2.5
  //   y4 = 1.75 + 0.5 * 2.5 - 0.25 * 2.5 = 2.375
  // (the DC gain is 1.75 / 0.75 = 2.33...).
  EXPECT_EQ((step_response<double, 2>({}, {1.0, 0.5, 0.25}, {1.0, -0.5, 0.25}, 5)),
            (std::vector<double>{1.0, 2.0, 2.5, 2.5, 2.375}));
  // The states after the first step: state0 = 0 + 0.5 * 1 - (-0.5) * 1 = 1, state1 = 0.25 * 1 - 0.25 * 1 = 0.
  DiscreteTransferFunction<double, 2> filter{};
  const std::array<double, 3> b{1.0, 0.5, 0.25};
  const std::array<double, 3> a{1.0, -0.5, 0.25};
  filter.update(1.0, b.data(), a.data());
  EXPECT_EQ(filter.state[0], 1.0);
  EXPECT_EQ(filter.state[1], 0.0);
}

TEST(BlocksDiscreteTransferFunction, StartsFromTheGivenState) {
  // 1 / (1 - z^-1), an accumulator: y = u + state, state = y. From state 3: 4, 5, 6.
  EXPECT_EQ((step_response<float, 1>({3.0F}, {1.0F, 0.0F}, {1.0F, -1.0F}, 3)), (std::vector<float>{4.0F, 5.0F, 6.0F}));
  // z^-1 as b = {0, 1}, a = {1, 0}: a unit delay, y = state, state = u.
  EXPECT_EQ((step_response<float, 1>({-2.0F}, {0.0F, 1.0F}, {1.0F, 0.0F}, 3)), (std::vector<float>{-2.0F, 1.0F, 1.0F}));
}

// The formulas of transfer_function.hpp as plain expressions, counting the steps where another order (feedforward
// and feedback swapped) would have given another state.
struct ReferenceSecondOrder {
  std::array<float, 2> state{};
  int order_mattered = 0;

  float step(float u, const std::array<float, 3>& b, const std::array<float, 3>& a) {
    const float y = (b[0] / a[0]) * u + state[0];
    const float s0 = (state[1] + (b[1] / a[0]) * u) - (a[1] / a[0]) * y;
    if (s0 != state[1] + ((b[1] / a[0]) * u - (a[1] / a[0]) * y)) ++order_mattered;
    state[1] = (b[2] / a[0]) * u - (a[2] / a[0]) * y;
    state[0] = s0;
    return y;
  }
};

TEST(BlocksDiscreteTransferFunction, MatchesTheReferenceBitForBit) {
  const std::array<float, 3> b{0.0675F, 0.135F, 0.0675F};
  const std::array<float, 3> a{1.3F, -1.143F, 0.413F};
  DiscreteTransferFunction<float, 2> filter{};
  ReferenceSecondOrder reference;
  for (const float u : {0.3F, -1.7F, 2.9F, 0.01F, -0.45F, 1.1F, 0.7F, -0.2F}) {
    EXPECT_EQ(filter.output(u, b.data(), a.data()), reference.step(u, b, a));
    filter.update(u, b.data(), a.data());
    EXPECT_EQ(filter.state[0], reference.state[0]);
    EXPECT_EQ(filter.state[1], reference.state[1]);
  }
  EXPECT_GT(reference.order_mattered, 0);
}

}  // namespace
}  // namespace duet::blocks
