#pragma once
// Discrete-time LQR and steady-state Kalman gains from the discrete algebraic Riccati equation (DARE)
//   S = A' S A - A' S B (R + B' S B)^-1 B' S A + Q,
// solved for its stabilising solution by the structured doubling algorithm, and by Newton's method where Q leaves an
// unstable mode unweighted (src/control/README.md).

#include <Eigen/Dense>

#include <optional>
#include <string>
#include <string_view>

#include "duet/support/result.hpp"

namespace duet::control {

struct RegulatorDesign {
  Eigen::MatrixXd gain;                      // K: u[k] = -K x[k], inputs x states
  Eigen::MatrixXd riccati;                   // S: the cost to go from x is x' S x
  Eigen::VectorXcd closed_loop_eigenvalues;  // of A - B K, largest magnitude first; all inside the unit circle
};

// The infinite-horizon regulator minimising the sum over k of x' Q x + u' R u for x[k+1] = A x[k] + B u[k].
// Preconditions checked, each with a message: A square (n x n), B n x m, Q n x n symmetric positive semi-definite,
// R m x m symmetric positive definite, all finite. Fails with a message when (A, B) is not stabilisable (a mode on or
// outside the unit circle that the inputs cannot move), when Q does not weigh a mode on the unit circle (then no
// stabilising solution exists) or when the iteration does not converge.
[[nodiscard]] Result<RegulatorDesign> dlqr(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::MatrixXd& q,
                                           const Eigen::MatrixXd& r);

struct KalmanDesign {
  // K in the current-estimate form: x[k|k] = x[k|k-1] + K (y[k] - C x[k|k-1]), then x[k+1|k] = A x[k|k] (+ B u[k]).
  Eigen::MatrixXd gain;                    // states x outputs
  Eigen::MatrixXd predicted_covariance;    // P = cov(x - x[k|k-1]), the solution of the dual DARE
  Eigen::MatrixXd filtered_covariance;     // cov(x - x[k|k]) = (I - K C) P
  Eigen::VectorXcd estimator_eigenvalues;  // of A (I - K C), the prediction error's dynamics, largest magnitude first
};

// The steady-state Kalman filter of x[k+1] = A x[k] + G w[k], y[k] = C x[k] + v[k], with white noises of covariance
// Q = cov(w) and R = cov(v), uncorrelated. The dual of dlqr: (A', C', G Q G', R). Preconditions as dlqr's (Q positive
// semi-definite, R positive definite); fails with a message when (A, C) is not detectable (a mode on or outside the
// unit circle that the outputs do not see) or the noise does not excite a mode on the unit circle.
[[nodiscard]] Result<KalmanDesign> kalman_gain(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c,
                                               const Eigen::MatrixXd& g, const Eigen::MatrixXd& q,
                                               const Eigen::MatrixXd& r);

// Why `weight` cannot be a weight or covariance matrix, if it cannot: not square, not symmetric, not positive
// semi-definite (positive definite when `definite`). The message starts with `name`: "R must be positive definite;
// ...".
[[nodiscard]] std::optional<std::string> weight_problem(std::string_view name, const Eigen::MatrixXd& weight,
                                                        bool definite);

// The eigenvalues of a square matrix, largest magnitude first (ties: larger real part, then larger imaginary part).
[[nodiscard]] Eigen::VectorXcd sorted_eigenvalues(const Eigen::MatrixXd& square);

}  // namespace duet::control
