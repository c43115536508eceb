#include "duet/control/discretise.hpp"

#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <string>

#include "duet/control/parameter_text.hpp"

namespace duet::control {

Result<DiscreteModel> c2d(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double period_s) {
  const Eigen::Index n = a.rows();
  const Eigen::Index m = b.cols();
  if (n == 0) return Failure{"A is empty: a model needs at least one state"};
  if (a.cols() != n) {
    return Failure{"A must be square; it is " + std::to_string(n) + "x" + std::to_string(a.cols())};
  }
  if (b.rows() != n) {
    return Failure{"B has " + std::to_string(b.rows()) + " rows; A has " + std::to_string(n) +
                   " (B needs one row per state)"};
  }
  if (!a.allFinite() || !b.allFinite()) return Failure{"A and B must hold finite numbers"};
  if (!std::isfinite(period_s) || period_s <= 0) {
    return Failure{"the period must be a positive number of seconds; it is " + number_text(period_s)};
  }
  // d/dt [x; u] = [[A, B], [0, 0]] [x; u] with u constant: the exponential over one period carries [x; u] from one
  // sample to the next, so its top blocks are Ad and Bd (Van Loan, "Computing integrals involving the matrix
  // exponential", 1978). Eigen's exp() scales and squares a Pade approximant.
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(n + m, n + m);
  block.topLeftCorner(n, n) = a * period_s;
  block.topRightCorner(n, m) = b * period_s;
  const Eigen::MatrixXd exponential = block.exp();
  return DiscreteModel{exponential.topLeftCorner(n, n), exponential.topRightCorner(n, m)};
}

}  // namespace duet::control
