#include "duet/blocks/kalman.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <type_traits>
#include <vector>

namespace duet::blocks {
namespace {

static_assert(std::is_aggregate_v<KalmanFilter<float, 2, 2, 1>> &&
              std::is_aggregate_v<SteadyStateKalmanFilter<float, 2, 1>>);
static_assert(sizeof(KalmanFilter<double, 2, 2, 1>) == 10 * sizeof(double));  // x, P and the step's K

constexpr double scalar_estimate_after_two_steps() {
  KalmanFilter<double, 1, 1, 1> filter{{0.0}, {1.0}};
  const double one[] = {1.0};
  const double y[] = {2.0};
  double first[1] = {};
  filter.output(y, one, one, first);  // K of the step, for update()
  filter.update(y, one, one, one, one);
  double estimate[1] = {};
  filter.output(y, one, one, estimate);
  return estimate[0];
}
static_assert(scalar_estimate_after_two_steps() > 1.599 && scalar_estimate_after_two_steps() < 1.601);

TEST(BlocksKalmanFilter, ScalarByHand) {
  // A = C = G = Q = R = 1, x0 = 0, P0 = 1, y = 2 every step. K = P / (P + 1), x[k|k] = x + K (2 - x),
  // P[k|k] = (1 - K) P, x+ = x[k|k], P+ = P[k|k] + 1:
  //   k = 0: K = 1/2;             x[k|k] = 0 + 2/2 = 1;            P[k|k] = 1/2;  P+ = 3/2
  //   k = 1: K = 1.5/2.5 = 3/5;   x[k|k] = 1 + (3/5) 1 = 8/5;      P[k|k] = 3/5;  P+ = 8/5
  //   k = 2: K = 1.6/2.6 = 8/13;  x[k|k] = 8/5 + (8/13)(2/5) = 24/13;  P[k|k] = 8/13;  P+ = 21/13
  KalmanFilter<double, 1, 1, 1> filter{{0.0}, {1.0}};
  const std::array<double, 1> one{1.0};
  const std::array<double, 1> y{2.0};
  const std::array<double, 3> expected_estimates{1.0, 8.0 / 5.0, 24.0 / 13.0};
  const std::array<double, 3> expected_covariances{3.0 / 2.0, 8.0 / 5.0, 21.0 / 13.0};
  for (std::size_t k = 0; k < 3; ++k) {
    std::array<double, 1> estimate{};
    filter.output(y.data(), one.data(), one.data(), estimate.data());
    EXPECT_DOUBLE_EQ(estimate[0], expected_estimates[k]) << k;
    filter.update(y.data(), one.data(), one.data(), one.data(), one.data());
    EXPECT_DOUBLE_EQ(filter.x[0], expected_estimates[k]) << k;  // A = 1: the prediction is the estimate
    EXPECT_DOUBLE_EQ(filter.p[0], expected_covariances[k]) << k;
  }
  // The first step is exact in float too.
  KalmanFilter<float, 1, 1, 1> in_float{{0.0F}, {1.0F}};
  const std::array<float, 1> one_f{1.0F};
  const std::array<float, 1> y_f{2.0F};
  std::array<float, 1> estimate_f{};
  in_float.output(y_f.data(), one_f.data(), one_f.data(), estimate_f.data());
  EXPECT_EQ(estimate_f[0], 1.0F);
  in_float.update(y_f.data(), one_f.data(), one_f.data(), one_f.data(), one_f.data());
  EXPECT_EQ(in_float.p[0], 1.5F);
}

TEST(BlocksKalmanFilter, SingularInnovationCovarianceLetsThePredictionThrough) {
  // P = 0 and R = 0: C P C^T + R = 0 is singular, so K = 0: x[k|k] = x, P[k|k] = P = 0, x+ = A x = 2 * 3,
  // P+ = 0 + G Q G^T = 0.5.
  KalmanFilter<double, 1, 1, 1> filter{{3.0}, {0.0}};
  const std::array<double, 1> y{100.0};
  const std::array<double, 1> a{2.0};
  const std::array<double, 1> c{1.0};
  const std::array<double, 1> g{1.0};
  const std::array<double, 1> q{0.5};
  const std::array<double, 1> r{0.0};
  std::array<double, 1> estimate{};
  filter.output(y.data(), c.data(), r.data(), estimate.data());
  EXPECT_EQ(estimate[0], 3.0);
  filter.update(y.data(), a.data(), c.data(), g.data(), q.data());
  EXPECT_EQ(filter.x[0], 6.0);
  EXPECT_EQ(filter.p[0], 0.5);
}

TEST(BlocksKalmanFilter, InputThroughB) {
  // The scalar step k = 0 of ScalarByHand with B = 4, u = 0.25: x+ = 1 + 4 * 0.25 = 2; P is not affected.
  KalmanFilter<double, 1, 1, 1> filter{{0.0}, {1.0}};
  const std::array<double, 1> one{1.0};
  const std::array<double, 1> y{2.0};
  const std::array<double, 1> b{4.0};
  const std::array<double, 1> u{0.25};
  std::array<double, 1> estimate{};
  filter.output(y.data(), one.data(), one.data(), estimate.data());
  filter.update(y.data(), u.data(), 1, one.data(), b.data(), one.data(), one.data(), one.data());
  EXPECT_EQ(filter.x[0], 2.0);
  EXPECT_EQ(filter.p[0], 1.5);
}

TEST(BlocksSteadyStateKalmanFilter, ScalarByHand) {
  // A = 2, C = 1, K = 0.5, x0 = 0, y = 4, 4: x[k|k] = x + 0.5 (4 - x), x+ = 2 x[k|k]:
  //   k = 0: x[k|k] = 2, x+ = 4;   k = 1: x[k|k] = 4 + 0 = 4, x+ = 8
  SteadyStateKalmanFilter<float, 1, 1> filter{{0.0F}};
  const std::array<float, 1> a{2.0F};
  const std::array<float, 1> c{1.0F};
  const std::array<float, 1> gain{0.5F};
  const std::array<float, 1> y{4.0F};
  std::vector<float> estimates;
  for (int k = 0; k < 2; ++k) {
    std::array<float, 1> estimate{};
    filter.output(y.data(), c.data(), gain.data(), estimate.data());
    estimates.push_back(estimate[0]);
    filter.update(y.data(), a.data(), c.data(), gain.data());
  }
  EXPECT_EQ(estimates, (std::vector<float>{2.0F, 4.0F}));
  EXPECT_EQ(filter.x[0], 8.0F);
  // With an input: B = 1, u = -3: x+ = 2 * (8 + 0.5 (4 - 8)) - 3 = 2 * 6 - 3 = 9.
  const std::array<float, 1> b{1.0F};
  const std::array<float, 1> u{-3.0F};
  filter.update(y.data(), u.data(), 1, a.data(), b.data(), c.data(), gain.data());
  EXPECT_EQ(filter.x[0], 9.0F);
}

TEST(BlocksSteadyStateKalmanFilter, TwoStatesOneMeasurement) {
  // Position and velocity with Ts = 0.5, position measured: A = [1 0.5; 0 1], C = [1 0], K = [0.5; 0.25].
  // From x = [0, 1] with y = 2: e = 2 - 0 = 2, x[k|k] = [1, 1.5], x+ = [1 + 0.75, 1.5] = [1.75, 1.5].
  SteadyStateKalmanFilter<double, 2, 1> filter{{0.0, 1.0}};
  const std::array<double, 4> a{1.0, 0.5, 0.0, 1.0};
  const std::array<double, 2> c{1.0, 0.0};
  const std::array<double, 2> gain{0.5, 0.25};
  const std::array<double, 1> y{2.0};
  std::array<double, 2> estimate{};
  filter.output(y.data(), c.data(), gain.data(), estimate.data());
  EXPECT_EQ(estimate, (std::array<double, 2>{1.0, 1.5}));
  filter.update(y.data(), a.data(), c.data(), gain.data());
  EXPECT_EQ(filter.x[0], 1.75);
  EXPECT_EQ(filter.x[1], 1.5);
}

// The thesis' tilt filter: state [angle, rate], both measured (angle from the accelerometer, rate from the gyroscope),
// the rate driven by white noise: A = [1 Ts; 0 1], C = I, G = [Ts; 1], Q = 9, R = diag(0.8, 330e-6), Ts = 1 ms.
// Units are degrees and degrees per second.
constexpr double thesis_period = 1e-3;

template <typename T>
struct ThesisMatrices {
  std::array<T, 4> a{T{1}, static_cast<T>(thesis_period), T{0}, T{1}};
  std::array<T, 4> c{T{1}, T{0}, T{0}, T{1}};
  std::array<T, 2> g{static_cast<T>(thesis_period), T{1}};
  std::array<T, 1> q{T{9}};
  std::array<T, 4> r{static_cast<T>(0.8), T{0}, T{0}, static_cast<T>(330e-6)};
};

// An independent reference in double, written out for 2 x 2 with C = I: S = P + R, S^-1 by the determinant,
// K = P S^-1, x[k|k] = x + K (y - x), P[k|k] = (I - K) P, x+ = A x[k|k], P+ = A P[k|k] A^T + G Q G^T.
struct Matrix2 {
  double m00;
  double m01;
  double m10;
  double m11;
};

struct Vector2 {
  double v0;
  double v1;
};

struct ThesisReference {
  Vector2 x{0.0, 0.0};
  Matrix2 p{1.0, 0.0, 0.0, 1.0};
  Vector2 estimate{0.0, 0.0};

  void step(double y0, double y1) {
    const double ts = thesis_period;
    const Matrix2 s{p.m00 + 0.8, p.m01, p.m10, p.m11 + 330e-6};
    const double det = s.m00 * s.m11 - s.m01 * s.m10;
    const Matrix2 inverse{s.m11 / det, -s.m01 / det, -s.m10 / det, s.m00 / det};
    const Matrix2 k{p.m00 * inverse.m00 + p.m01 * inverse.m10, p.m00 * inverse.m01 + p.m01 * inverse.m11,
                    p.m10 * inverse.m00 + p.m11 * inverse.m10, p.m10 * inverse.m01 + p.m11 * inverse.m11};
    const Vector2 e{y0 - x.v0, y1 - x.v1};
    estimate = {x.v0 + k.m00 * e.v0 + k.m01 * e.v1, x.v1 + k.m10 * e.v0 + k.m11 * e.v1};
    const Matrix2 f{(1 - k.m00) * p.m00 - k.m01 * p.m10, (1 - k.m00) * p.m01 - k.m01 * p.m11,
                    -k.m10 * p.m00 + (1 - k.m11) * p.m10, -k.m10 * p.m01 + (1 - k.m11) * p.m11};
    x = {estimate.v0 + ts * estimate.v1, estimate.v1};
    // A F A^T with A = [1 ts; 0 1], plus G Q G^T = 9 [ts^2 ts; ts 1].
    p = {f.m00 + ts * (f.m10 + f.m01) + ts * ts * f.m11 + 9 * ts * ts, f.m01 + ts * f.m11 + 9 * ts,
         f.m10 + ts * f.m11 + 9 * ts, f.m11 + 9};
  }
};

// Noisy measurements of a constant tilt of 10 degrees and rate 0, from a fixed seed.
std::vector<std::array<double, 2>> thesis_measurements(std::size_t steps) {
  std::mt19937 generator(20240611U);
  std::normal_distribution<double> angle_noise(0.0, std::sqrt(0.8));
  std::normal_distribution<double> rate_noise(0.0, std::sqrt(330e-6));
  std::vector<std::array<double, 2>> measurements(steps);
  for (auto& y : measurements) y = {10.0 + angle_noise(generator), rate_noise(generator)};
  return measurements;
}

struct ThesisRun {
  double largest_estimate_difference = 0.0;    // against the reference, relative to 1 + |reference|
  double largest_covariance_difference = 0.0;  // relative to 1e-3 + |reference| (P[0][0] falls to about 1e-4)
  double largest_error_after_settling = 0.0;   // |angle estimate - 10| from step 200 on
};

template <typename T>
ThesisRun run_thesis_filter(std::size_t steps) {
  const ThesisMatrices<T> m;
  KalmanFilter<T, 2, 2, 1> filter{{T{0}, T{0}}, {T{1}, T{0}, T{0}, T{1}}};
  ThesisReference reference;
  ThesisRun run;
  const auto measurements = thesis_measurements(steps);
  for (std::size_t k = 0; k < steps; ++k) {
    const std::array<T, 2> y{static_cast<T>(measurements[k][0]), static_cast<T>(measurements[k][1])};
    std::array<T, 2> estimate{};
    filter.output(y.data(), m.c.data(), m.r.data(), estimate.data());
    filter.update(y.data(), m.a.data(), m.c.data(), m.g.data(), m.q.data());
    reference.step(static_cast<double>(y[0]), static_cast<double>(y[1]));
    const auto relative = [](double value, double expected, double floor) {
      return std::abs(value - expected) / (floor + std::abs(expected));
    };
    run.largest_estimate_difference =
        std::max({run.largest_estimate_difference, relative(estimate[0], reference.estimate.v0, 1.0),
                  relative(estimate[1], reference.estimate.v1, 1.0)});
    run.largest_covariance_difference =
        std::max({run.largest_covariance_difference, relative(filter.p[0], reference.p.m00, 1e-3),
                  relative(filter.p[1], reference.p.m01, 1e-3), relative(filter.p[2], reference.p.m10, 1e-3),
                  relative(filter.p[3], reference.p.m11, 1e-3)});
    if (k >= 200) {
      run.largest_error_after_settling =
          std::max(run.largest_error_after_settling, std::abs(static_cast<double>(estimate[0]) - 10.0));
    }
  }
  return run;
}

TEST(BlocksKalmanFilter, ThesisTiltFilterMatchesTheReferenceAndConverges) {
  const auto in_double = run_thesis_filter<double>(3000);
  // Measured: about 3e-15 and 1e-14 (Gauss-Jordan against the determinant formula, other orders of summation).
  EXPECT_LT(in_double.largest_estimate_difference, 1e-12);
  EXPECT_LT(in_double.largest_covariance_difference, 1e-12);
  EXPECT_LT(in_double.largest_error_after_settling, 0.5);
  const auto in_float = run_thesis_filter<float>(3000);
  // Measured: about 2e-6 and 6e-6 (float's epsilon is 1.2e-7; the errors accumulate over the steps).
  EXPECT_LT(in_float.largest_estimate_difference, 1e-5);
  EXPECT_LT(in_float.largest_covariance_difference, 5e-5);
  EXPECT_LT(in_float.largest_error_after_settling, 0.5);
}

}  // namespace
}  // namespace duet::blocks
