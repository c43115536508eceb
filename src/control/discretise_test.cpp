// Zero-order hold against discretisations known in closed form.
#include "duet/control/discretise.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace duet::control {
namespace {

TEST(Discretise, DoubleIntegrator) {
  // x'' = u held for Ts: x gains v Ts + u Ts^2 / 2, v gains u Ts.
  for (const double ts : {1e-3, 0.1, 2.0}) {
    const Eigen::Matrix2d a{{0, 1}, {0, 0}};
    const Eigen::Vector2d b{0, 1};
    auto model = c2d(a, b, ts);
    ASSERT_TRUE(model) << model.error();
    const Eigen::Matrix2d ad{{1, ts}, {0, 1}};
    const Eigen::Vector2d bd{ts * ts / 2, ts};
    EXPECT_LE((model.value().ad - ad).norm(), 1e-14) << model.value().ad;
    EXPECT_LE((model.value().bd - bd).norm(), 1e-14 * ts) << model.value().bd;
  }
}

TEST(Discretise, FirstOrderLag) {
  // x' = -2 x + 3 u over 0.5 s: x decays by e^-1; a held u adds 3 u (1 - e^-1) / 2.
  auto model = c2d(Eigen::MatrixXd::Constant(1, 1, -2), Eigen::MatrixXd::Constant(1, 1, 3), 0.5);
  ASSERT_TRUE(model) << model.error();
  EXPECT_NEAR(model.value().ad(0, 0), std::exp(-1.0), 1e-15);
  EXPECT_NEAR(model.value().bd(0, 0), 1.5 * (1 - std::exp(-1.0)), 1e-15);
}

TEST(Discretise, Oscillator) {
  // x'' = -w^2 x + u: the state rotates by w Ts; a held u pulls x towards u / w^2.
  const double w = 3;
  const double ts = 0.2;
  const Eigen::Matrix2d a{{0, 1}, {-w * w, 0}};
  auto model = c2d(a, Eigen::Vector2d{0, 1}, ts);
  ASSERT_TRUE(model) << model.error();
  const double cosine = std::cos(w * ts);
  const double sine = std::sin(w * ts);
  const Eigen::Matrix2d ad{{cosine, sine / w}, {-w * sine, cosine}};
  const Eigen::Vector2d bd{(1 - cosine) / (w * w), sine / w};
  EXPECT_LE((model.value().ad - ad).norm(), 1e-14) << model.value().ad;
  EXPECT_LE((model.value().bd - bd).norm(), 1e-14) << model.value().bd;
}

TEST(Discretise, SaysWhatIsWrong) {
  const Eigen::MatrixXd square = Eigen::MatrixXd::Identity(2, 2);
  auto not_square = c2d(Eigen::MatrixXd::Zero(2, 3), Eigen::MatrixXd::Zero(2, 1), 0.1);
  ASSERT_FALSE(not_square);
  EXPECT_EQ(not_square.error(), "A must be square; it is 2x3");
  auto rows = c2d(square, Eigen::MatrixXd::Zero(3, 1), 0.1);
  ASSERT_FALSE(rows);
  EXPECT_EQ(rows.error(), "B has 3 rows; A has 2 (B needs one row per state)");
  EXPECT_FALSE(c2d(square, Eigen::MatrixXd::Zero(2, 1), 0));
  EXPECT_FALSE(c2d(square, Eigen::MatrixXd::Zero(2, 1), std::nan("")));
  EXPECT_FALSE(c2d(Eigen::MatrixXd::Constant(1, 1, INFINITY), Eigen::MatrixXd::Zero(1, 1), 0.1));
}

}  // namespace
}  // namespace duet::control
