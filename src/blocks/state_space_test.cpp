#include "duet/blocks/state_space.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

namespace duet::blocks {
namespace {

static_assert(std::is_aggregate_v<DiscreteStateSpace<float, 2, 1, 1>>);
static_assert(sizeof(DiscreteStateSpace<double, 3, 2, 1>) == 3 * sizeof(double));

// A double integrator with Ts = 0.5: position, velocity; acceleration u.
//   A = [1 0.5; 0 1], B = [0.125; 0.5] (Ts^2 / 2, Ts)
constexpr std::array<double, 4> double_integrator_a{1.0, 0.5, 0.0, 1.0};
constexpr std::array<double, 2> double_integrator_b{0.125, 0.5};

constexpr double position_after_three_steps() {
  DiscreteStateSpace<double, 2, 1, 1> system{};
  const double u[] = {1.0};
  for (int k = 0; k < 3; ++k) system.update(u, double_integrator_a.data(), double_integrator_b.data());
  return system.x[0];
}
static_assert(position_after_three_steps() == 1.125);

TEST(BlocksDiscreteStateSpace, DoubleIntegratorByHand) {
  // y = [1 0] x, D = 0; u = 1 from rest:
  //   k = 0: y = 0;      x = [0 + 0 + 0.125, 0 + 0.5] = [0.125, 0.5]
  //   k = 1: y = 0.125;  x = [0.125 + 0.25 + 0.125, 0.5 + 0.5] = [0.5, 1]
  //   k = 2: y = 0.5;    x = [0.5 + 0.5 + 0.125, 1 + 0.5] = [1.125, 1.5]
  //   k = 3: y = 1.125   (t^2 / 2 at t = 1.5)
  const std::array<double, 2> c{1.0, 0.0};
  const std::array<double, 1> d{0.0};
  const std::array<double, 1> u{1.0};
  DiscreteStateSpace<double, 2, 1, 1> system{};
  std::vector<double> outputs;
  for (int k = 0; k < 4; ++k) {
    std::array<double, 1> y{};
    system.output(u.data(), c.data(), d.data(), y.data());
    outputs.push_back(y[0]);
    system.update(u.data(), double_integrator_a.data(), double_integrator_b.data());
  }
  EXPECT_EQ(outputs, (std::vector<double>{0.0, 0.125, 0.5, 1.125}));
  EXPECT_EQ(system.x[1], 2.0);
}

TEST(BlocksDiscreteStateSpace, TwoOutputsWithFeedthrough) {
  // C = I, D = [1; -1]: y = [x0 + u, x1 - u]. From x = [0.5, -0.25] with u = 2: y = [2.5, -2.25].
  const std::array<float, 4> c{1.0F, 0.0F, 0.0F, 1.0F};
  const std::array<float, 2> d{1.0F, -1.0F};
  const std::array<float, 1> u{2.0F};
  const DiscreteStateSpace<float, 2, 1, 2> system{{0.5F, -0.25F}};
  std::array<float, 2> y{};
  system.output(u.data(), c.data(), d.data(), y.data());
  EXPECT_EQ(y, (std::array<float, 2>{2.5F, -2.25F}));
}

TEST(BlocksDiscreteStateSpace, TwoInputsAndNoInputs) {
  // x(k+1) = 0.5 x + [1 -1] u: from 4 with u = [3, 1]: 2 + 3 - 1 = 4; with u = [0.5, 2]: 2 + 0.5 - 2 = 0.5.
  const std::array<double, 1> a{0.5};
  const std::array<double, 2> b{1.0, -1.0};
  DiscreteStateSpace<double, 1, 2, 1> system{{4.0}};
  const std::array<double, 2> u0{3.0, 1.0};
  system.update(u0.data(), a.data(), b.data());
  EXPECT_EQ(system.x[0], 4.0);
  const std::array<double, 2> u1{0.5, 2.0};
  system.update(u1.data(), a.data(), b.data());
  EXPECT_EQ(system.x[0], 0.5);
  // NU = 0: an autonomous system, x halves each step; u, b and d are not read.
  DiscreteStateSpace<double, 1, 0, 1> autonomous{{4.0}};
  autonomous.update(nullptr, a.data(), nullptr);
  const std::array<double, 1> c{3.0};
  std::array<double, 1> y{};
  autonomous.output(nullptr, c.data(), nullptr, y.data());
  EXPECT_EQ(y[0], 6.0);
}

TEST(BlocksDiscreteStateSpace, OneRunningSumLeftToRight) {
  // Float's spacing at 1e8 is 8, so 1e8 + 1 rounds to 1e8. With x = [1, 1e8], C = [1 1], D = [1], u = -1e8:
  //   left to right  (1 + 1e8) - 1e8 = 0         right to left  (-1e8 + 1e8) + 1 = 1
  const std::array<float, 2> c{1.0F, 1.0F};
  const std::array<float, 1> d{1.0F};
  const std::array<float, 1> u{-1e8F};
  const DiscreteStateSpace<float, 2, 1, 1> system{{1.0F, 1e8F}};
  std::array<float, 1> y{-5.0F};
  system.output(u.data(), c.data(), d.data(), y.data());
  EXPECT_EQ(y[0], 0.0F);
  // x(k+1) likewise: A = [1 1; 0 0], B = [1; 0].
  const std::array<float, 4> a{1.0F, 1.0F, 0.0F, 0.0F};
  const std::array<float, 2> b{1.0F, 0.0F};
  DiscreteStateSpace<float, 2, 1, 1> stepped = system;
  stepped.update(u.data(), a.data(), b.data());
  EXPECT_EQ(stepped.x[0], 0.0F);
  EXPECT_EQ(stepped.x[1], 0.0F);
  // C x and D u are one sum, not two added: x = [1e8, 1], u = [-1e8, 1], C = [1 1], D = [1 1]:
  //   one running sum  ((1e8 + 1) - 1e8) + 1 = 1     C x + D u apart  (1e8 + 1) + (-1e8 + 1) = 1e8 - 1e8 = 0
  const std::array<float, 2> d2{1.0F, 1.0F};
  const std::array<float, 2> u2{-1e8F, 1.0F};
  const DiscreteStateSpace<float, 2, 2, 1> two_inputs{{1e8F, 1.0F}};
  two_inputs.output(u2.data(), c.data(), d2.data(), y.data());
  EXPECT_EQ(y[0], 1.0F);
}

TEST(BlocksStateFeedback, MinusKTimesX) {
  // K = [1 2; 3 4], x = [0.5, -1]: u = -[0.5 - 2, 1.5 - 4] = [1.5, 2.5].
  const std::array<double, 4> k{1.0, 2.0, 3.0, 4.0};
  const std::array<double, 2> x{0.5, -1.0};
  std::array<double, 2> u{};
  state_feedback(k.data(), x.data(), 2, 2, u.data());
  EXPECT_EQ(u, (std::array<double, 2>{1.5, 2.5}));
  // One input from three states, the robot's shape: K = [2 -1 0.5], x = [1, 2, 4]: u = -(2 - 2 + 2) = -2.
  const std::array<float, 3> k3{2.0F, -1.0F, 0.5F};
  const std::array<float, 3> x3{1.0F, 2.0F, 4.0F};
  std::array<float, 1> u1{};
  state_feedback(k3.data(), x3.data(), 1, 3, u1.data());
  EXPECT_EQ(u1[0], -2.0F);
}

TEST(BlocksStateFeedback, SumsLeftToRightThenNegates) {
  // (1 + 1e8) - 1e8 = 0 in float, negated -0.0; summed the other way it would be 1.
  const std::array<float, 3> k{1.0F, 1e8F, -1e8F};
  const std::array<float, 3> x{1.0F, 1.0F, 1.0F};
  std::array<float, 1> u{5.0F};
  state_feedback(k.data(), x.data(), 1, 3, u.data());
  EXPECT_EQ(u[0], 0.0F);
  EXPECT_TRUE(std::signbit(u[0]));
  state_feedback<float>(nullptr, nullptr, 1, 0, u.data());
  EXPECT_TRUE(u[0] == 0.0F && std::signbit(u[0]));
}

}  // namespace
}  // namespace duet::blocks
