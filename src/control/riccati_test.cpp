// The regulator's Riccati equation: by hand, against its own definition, against the Riccati recursion, and the
// problems it cannot solve.
#include "duet/control/riccati.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "duet/control/balbot_model.hpp"

namespace duet::control {
namespace {

Eigen::MatrixXd scalar(double value) { return Eigen::MatrixXd::Constant(1, 1, value); }

// || S - (A' S A - A' S B (R + B' S B)^-1 B' S A + Q) || / || S ||
double dare_residual(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::MatrixXd& q,
                     const Eigen::MatrixXd& r, const Eigen::MatrixXd& s) {
  const Eigen::MatrixXd bsa = b.transpose() * s * a;
  const Eigen::MatrixXd right =
      a.transpose() * s * a - bsa.transpose() * (r + b.transpose() * s * b).inverse() * bsa + q;
  return (s - right).norm() / s.norm();
}

TEST(Dlqr, ScalarByHand) {
  // a = b = q = r = 1: s = s - s^2 / (1 + s) + 1, so s^2 = 1 + s: s = (1 + sqrt 5) / 2; k = b s a / (r + b s b).
  auto design = dlqr(scalar(1), scalar(1), scalar(1), scalar(1));
  ASSERT_TRUE(design) << design.error();
  const double s = (1 + std::sqrt(5.0)) / 2;
  EXPECT_NEAR(design.value().riccati(0, 0), s, 1e-13);
  EXPECT_NEAR(design.value().gain(0, 0), s / (1 + s), 1e-13);
  EXPECT_NEAR(design.value().closed_loop_eigenvalues(0).real(), 1 - s / (1 + s), 1e-13);
}

TEST(Dlqr, CheapestStabilisationMirrorsTheUnstablePole) {
  // a = 2, b = 1, q = 0, r = 1: s = 4 s - 4 s^2 / (1 + s) has the solutions 0 (no control: unstable) and 3. The
  // stabilising one is 3: k = 2 * 3 / (1 + 3) = 1.5, and the closed loop 2 - 1.5 = 0.5 = 1 / a.
  auto design = dlqr(scalar(2), scalar(1), scalar(0), scalar(1));
  ASSERT_TRUE(design) << design.error();
  EXPECT_NEAR(design.value().riccati(0, 0), 3, 1e-12);
  EXPECT_NEAR(design.value().gain(0, 0), 1.5, 1e-12);
  EXPECT_NEAR(design.value().closed_loop_eigenvalues(0).real(), 0.5, 1e-12);
}

struct Robot {
  DiscreteModel model;
  Eigen::MatrixXd q = Eigen::Vector4d{1, 1, 100, 1}.asDiagonal();
  Eigen::MatrixXd r = Eigen::MatrixXd::Constant(1, 1, 0.1);
};

Robot robot(double period_s) {
  auto continuous = linearise_balbot();
  EXPECT_TRUE(continuous) << continuous.error();
  auto discrete = c2d(continuous.value().a, continuous.value().b, period_s);
  EXPECT_TRUE(discrete) << discrete.error();
  return Robot{discrete.value()};
}

TEST(Dlqr, BalancesTheRobot) {
  for (const double period_s : {1e-3, 1e-2}) {
    const Robot plant = robot(period_s);
    ASSERT_GT(sorted_eigenvalues(plant.model.ad).cwiseAbs().maxCoeff(), 1.001);  // upright is unstable
    auto design = dlqr(plant.model.ad, plant.model.bd, plant.q, plant.r);
    ASSERT_TRUE(design) << design.error();
    const Eigen::MatrixXd closed = plant.model.ad - plant.model.bd * design.value().gain;
    const Eigen::VectorXcd eigenvalues = Eigen::EigenSolver<Eigen::MatrixXd>{closed}.eigenvalues();
    EXPECT_LT(eigenvalues.cwiseAbs().maxCoeff(), 1) << eigenvalues;
    EXPECT_NEAR(design.value().closed_loop_eigenvalues.cwiseAbs().maxCoeff(), eigenvalues.cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LE(dare_residual(plant.model.ad, plant.model.bd, plant.q, plant.r, design.value().riccati), 1e-9);
    // Falling forward (theta < 0: the body ahead of the axle) must drive the wheels forward (u = -K x > 0) to get
    // under it, so K's tilt entry is positive.
    EXPECT_GT(design.value().gain(0, 2), 0) << design.value().gain;
  }
}

TEST(Dlqr, AgreesWithTheRiccatiRecursion) {
  // S[k+1] = A' S[k] A - A' S[k] B (R + B' S[k] B)^-1 B' S[k] A + Q from S = Q, step by step until it stops moving.
  const Robot plant = robot(1e-2);
  const Eigen::MatrixXd& a = plant.model.ad;
  const Eigen::MatrixXd& b = plant.model.bd;
  Eigen::MatrixXd s = plant.q;
  for (int step = 0; step < 1'000'000; ++step) {
    const Eigen::MatrixXd bsa = b.transpose() * s * a;
    const Eigen::MatrixXd next =
        a.transpose() * s * a - bsa.transpose() * (plant.r + b.transpose() * s * b).inverse() * bsa + plant.q;
    const double change = (next - s).norm();
    s = (next + next.transpose()) / 2;
    if (change <= 1e-13 * s.norm()) break;
  }
  auto design = dlqr(a, b, plant.q, plant.r);
  ASSERT_TRUE(design) << design.error();
  EXPECT_LE((design.value().riccati - s).norm(), 1e-9 * s.norm());
  const Eigen::MatrixXd k = (plant.r + b.transpose() * s * b).inverse() * b.transpose() * s * a;
  EXPECT_LE((design.value().gain - k).norm(), 1e-9 * k.norm()) << design.value().gain << "\n" << k;
}

TEST(Dlqr, AStableModeTheInputCannotReachIsFine) {
  // The reachable mode alone: a = 2, b = q = r = 1 gives s^2 - 4 s - 1 = 0, s = 2 + sqrt 5, k = 2 s / (1 + s), the
  // closed loop 2 - k = 0.381966; the unreachable 0.5 stays where it is.
  const Eigen::Matrix2d a{{0.5, 0}, {0, 2}};
  auto design = dlqr(a, Eigen::Vector2d{0, 1}, Eigen::Matrix2d::Identity(), scalar(1));
  ASSERT_TRUE(design) << design.error();
  const double s = 2 + std::sqrt(5.0);
  EXPECT_NEAR(design.value().closed_loop_eigenvalues(0).real(), 0.5, 1e-12);
  EXPECT_NEAR(design.value().closed_loop_eigenvalues(1).real(), 2 - 2 * s / (1 + s), 1e-12);
  EXPECT_NEAR(design.value().riccati(1, 1), s, 1e-12);
}

TEST(Dlqr, RefusesWhatHasNoStabilisingGain) {
  const Eigen::Matrix2d a{{2, 0}, {0, 0.5}};
  auto unreachable = dlqr(a, Eigen::Vector2d{0, 1}, Eigen::Matrix2d::Identity(), scalar(1));
  ASSERT_FALSE(unreachable);
  EXPECT_EQ(unreachable.error(),
            "(A, B) is not stabilisable: the inputs cannot move the mode at eigenvalue 2 (magnitude 2)");
  // An integrator the weights ignore: any gain 0 <= k < 2 is as good as none, and none leaves it on the circle.
  auto unweighted = dlqr(scalar(1), scalar(1), scalar(0), scalar(1));
  ASSERT_FALSE(unweighted);
  EXPECT_NE(unweighted.error().find("Q does not weigh the mode on the unit circle at eigenvalue 1"), std::string::npos)
      << unweighted.error();
}

TEST(Dlqr, RefusesWrongSizesAndWeights) {
  const Eigen::Matrix2d a = Eigen::Matrix2d::Identity();
  const Eigen::Vector2d b{0, 1};
  const Eigen::Matrix2d q = Eigen::Matrix2d::Identity();
  auto r_size = dlqr(a, b, q, Eigen::Matrix2d::Identity());
  ASSERT_FALSE(r_size);
  EXPECT_EQ(r_size.error(), "R must be 1x1 (one row and column per input); it is 2x2");
  auto q_size = dlqr(a, b, scalar(1), scalar(1));
  ASSERT_FALSE(q_size);
  EXPECT_EQ(q_size.error(), "Q must be 2x2 like A; it is 1x1");
  auto r_zero = dlqr(a, b, q, scalar(0));
  ASSERT_FALSE(r_zero);
  EXPECT_EQ(r_zero.error().rfind("R must be positive definite", 0), 0U) << r_zero.error();
  auto q_asymmetric = dlqr(a, b, Eigen::Matrix2d{{1, 1}, {0, 1}}, scalar(1));
  ASSERT_FALSE(q_asymmetric);
  EXPECT_EQ(q_asymmetric.error(), "Q must be symmetric");
  auto q_indefinite = dlqr(a, b, Eigen::Matrix2d{{1, 0}, {0, -1}}, scalar(1));
  ASSERT_FALSE(q_indefinite);
  EXPECT_EQ(q_indefinite.error().rfind("Q must be positive semi-definite", 0), 0U) << q_indefinite.error();
  EXPECT_FALSE(dlqr(a, Eigen::Vector2d{0, NAN}, q, scalar(1)));
}

TEST(SortedEigenvalues, LargestFirstConjugatesTogether) {
  const Eigen::Matrix3d m{{0.5, 0, 0}, {0, 0, -0.8}, {0, 0.8, 0}};  // 0.5 and +-0.8i
  const Eigen::VectorXcd values = sorted_eigenvalues(m);
  ASSERT_EQ(values.size(), 3);
  EXPECT_NEAR(values(0).imag(), 0.8, 1e-15);
  EXPECT_NEAR(values(1).imag(), -0.8, 1e-15);
  EXPECT_NEAR(values(2).real(), 0.5, 1e-15);
}

}  // namespace
}  // namespace duet::control
