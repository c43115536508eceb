// The steady-state Kalman gain: by hand, and against the time-varying filter it is the limit of.
#include <gtest/gtest.h>

#include <cmath>

#include "duet/control/riccati.hpp"

namespace duet::control {
namespace {

Eigen::MatrixXd scalar(double value) { return Eigen::MatrixXd::Constant(1, 1, value); }

TEST(KalmanGain, ScalarByHand) {
  // A random walk (a = c = g = 1) with q = r = 1: the prior variance solves p = p - p^2 / (p + 1) + 1, p^2 = p + 1,
  // p = (1 + sqrt 5) / 2, and the gain p / (p + 1) = 1 / p; the filtered variance is (1 - k) p = k.
  auto design = kalman_gain(scalar(1), scalar(1), scalar(1), scalar(1), scalar(1));
  ASSERT_TRUE(design) << design.error();
  const double p = (1 + std::sqrt(5.0)) / 2;
  EXPECT_NEAR(design.value().predicted_covariance(0, 0), p, 1e-13);
  EXPECT_NEAR(design.value().gain(0, 0), 1 / p, 1e-13);
  EXPECT_NEAR(design.value().filtered_covariance(0, 0), 1 / p, 1e-13);
  EXPECT_NEAR(design.value().estimator_eigenvalues(0).real(), 1 - 1 / p, 1e-13);
}

TEST(KalmanGain, TheThesisTiltFilterIsTheLimitOfTheTimeVaryingFilter) {
  // Thesis eqs. 5.7-5.11: x = [theta (deg), gyro rate (deg/s)], both measured; the rate is a random walk driven by
  // noise of variance 9 entering through G = [Ts, 1]'.
  const double ts = 1e-3;
  const Eigen::Matrix2d a{{1, ts}, {0, 1}};
  const Eigen::Matrix2d c = Eigen::Matrix2d::Identity();
  const Eigen::Vector2d g{ts, 1};
  const Eigen::MatrixXd q = Eigen::MatrixXd::Constant(1, 1, 9);
  const Eigen::Matrix2d r = Eigen::Vector2d{0.8, 330e-6}.asDiagonal();
  auto design = kalman_gain(a, c, g, q, r);
  ASSERT_TRUE(design) << design.error();

  // The filter as it runs from an uncertain start: correct with the measurement, then predict; written out for the
  // 2x2 case. Its slowest mode is the tilt's (gain about 2e-5 per step: a 50 s time constant at 1 kHz), so the
  // covariance needs some 10^6 steps, not a few thousand, to settle to 1e-9.
  double p11 = 100;
  double p12 = 0;
  double p22 = 100;
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
  for (int step = 0; step < 1'500'000; ++step) {
    const double s11 = p11 + 0.8;
    const double s22 = p22 + 330e-6;
    const double det = s11 * s22 - p12 * p12;
    // K = P S^-1 with S = P + R; S^-1 = [[s22, -p12], [-p12, s11]] / det.
    const double k11 = (p11 * s22 - p12 * p12) / det;
    const double k12 = (p12 * s11 - p11 * p12) / det;
    const double k21 = (p12 * s22 - p22 * p12) / det;
    const double k22 = (p22 * s11 - p12 * p12) / det;
    // Filtered: (I - K) P.
    const double f11 = p11 - (k11 * p11 + k12 * p12);
    const double f12 = p12 - (k11 * p12 + k12 * p22);
    const double f22 = p22 - (k21 * p12 + k22 * p22);
    // Predicted: A F A' + G Q G' with A = [[1, Ts], [0, 1]], G = [Ts, 1]'.
    p11 = f11 + 2 * ts * f12 + ts * ts * f22 + 9 * ts * ts;
    p12 = f12 + ts * f22 + 9 * ts;
    p22 = f22 + 9;
    k << k11, k12, k21, k22;
  }
  const Eigen::Matrix2d p{{p11, p12}, {p12, p22}};
  EXPECT_LE((design.value().gain - k).norm(), 1e-9 * k.norm()) << design.value().gain << "\n" << k;
  EXPECT_LE((design.value().predicted_covariance - p).norm(), 1e-9 * p.norm());
  // The rate is measured far better than the process lets it wander: the gyro is trusted almost fully; the
  // accelerometer's tilt only a little, in favour of the integrated rate.
  EXPECT_GT(design.value().gain(1, 1), 0.9);
  EXPECT_LT(design.value().gain(0, 0), 0.1);
  EXPECT_LT(design.value().estimator_eigenvalues.cwiseAbs().maxCoeff(), 1);
}

TEST(KalmanGain, RefusesWhatTheOutputsCannotSee) {
  const Eigen::Matrix2d a{{1.5, 0}, {0, 0.5}};
  auto blind =
      kalman_gain(a, Eigen::RowVector2d{0, 1}, Eigen::Matrix2d::Identity(), Eigen::Matrix2d::Identity(), scalar(1));
  ASSERT_FALSE(blind);
  EXPECT_EQ(blind.error(),
            "(A, C) is not detectable: the outputs do not see the mode at eigenvalue 1.5 (magnitude 1.5)");
  auto sizes = kalman_gain(a, Eigen::RowVector2d{0, 1}, Eigen::Matrix2d::Identity(), scalar(1), scalar(1));
  ASSERT_FALSE(sizes);
  EXPECT_EQ(sizes.error(), "Q must be 2x2 (one row and column per noise input, a column of G); it is 1x1");
}

}  // namespace
}  // namespace duet::control
