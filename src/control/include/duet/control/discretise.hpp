#pragma once
// Zero-order-hold discretisation of a continuous-time linear model x' = A x + B u.

#include <Eigen/Dense>

#include "duet/support/result.hpp"

namespace duet::control {

// x' = a x + b u.
struct ContinuousModel {
  Eigen::MatrixXd a;
  Eigen::MatrixXd b;
};

// x[k+1] = ad x[k] + bd u[k], u held constant over each period.
struct DiscreteModel {
  Eigen::MatrixXd ad;
  Eigen::MatrixXd bd;
};

// Ad = e^(A Ts), Bd = (integral from 0 to Ts of e^(A t) dt) B, both read off one exponential of the block matrix
// [[A, B], [0, 0]] Ts. Fails (with the reason) when A is not square, B's rows differ from A's, an entry is not finite
// or period_s is not a positive finite number of seconds. Any number of inputs, also none (B with 0 columns).
[[nodiscard]] Result<DiscreteModel> c2d(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double period_s);

}  // namespace duet::control
