#include "duet/control/riccati.hpp"

#include <algorithm>
#include <complex>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include "duet/control/parameter_text.hpp"

namespace duet::control {
namespace {

// The doubling converges quadratically once the closed loop's slowest mode has been squared enough times; 64 doublings
// stand for 2^64 steps of the Riccati difference equation, far past any slowest mode that rounds to inside the circle.
constexpr int max_doublings = 64;
constexpr int max_newton_steps = 100;      // quadratic from a stabilising start; linear only where no solution exists
constexpr double converged = 1e-14;        // relative change of S between doublings
constexpr double rank_tolerance = 1e-10;   // smallest / largest singular value of [lambda I - A, B]
constexpr double unit_circle = 1 - 1e-10;  // modes at least this large count as on or outside the unit circle

std::string size_text(const Eigen::MatrixXd& m) { return std::to_string(m.rows()) + "x" + std::to_string(m.cols()); }

std::string eigenvalue_text(std::complex<double> value) {
  std::ostringstream text;
  text.precision(6);
  text << value.real();
  if (value.imag() != 0) text << (value.imag() < 0 ? " - " : " + ") << std::abs(value.imag()) << "i";
  text << " (magnitude " << std::abs(value) << ")";
  return text.str();
}

// How the failures of the DARE read: for a regulator, or for a filter (the dual problem).
struct Wording {
  std::string not_stabilisable;  // followed by the eigenvalue
  std::string no_stabilising_solution;
};

std::optional<Failure> check_weights(const Eigen::MatrixXd& q, const Eigen::MatrixXd& r) {
  if (auto problem = weight_problem("Q", q, false)) return Failure{*problem};
  if (auto problem = weight_problem("R", r, true)) return Failure{*problem};
  return std::nullopt;
}

// A mode on or outside the unit circle that the inputs cannot move: the Popov-Belevitch-Hautus test, rank
// [lambda I - A, B] < n for an eigenvalue lambda of A.
std::optional<std::complex<double>> unreachable_mode(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  const Eigen::Index n = a.rows();
  const Eigen::VectorXcd modes = sorted_eigenvalues(a);
  for (const std::complex<double> mode : modes) {
    if (std::abs(mode) < unit_circle) break;  // sorted: the rest are inside
    Eigen::MatrixXcd pencil(n, n + b.cols());
    pencil.leftCols(n) = mode * Eigen::MatrixXcd::Identity(n, n) - a.cast<std::complex<double>>();
    pencil.rightCols(b.cols()) = b.cast<std::complex<double>>();
    const Eigen::VectorXd singular = Eigen::JacobiSVD<Eigen::MatrixXcd>{pencil}.singularValues();
    if (singular(n - 1) <= rank_tolerance * singular(0)) return mode;
  }
  return std::nullopt;
}

// S from the structured doubling algorithm (Chu, Fan, Lin and Wang, 2004): with G = B R^-1 B', iterate
//   A+ = A (I + G H)^-1 A,  G+ = G + A (I + G H)^-1 G A',  H+ = H + A' H (I + G H)^-1 A
// from (A, G, Q). Each doubling stands for twice as many steps of the Riccati recursion from S = 0, so H converges to
// the solution that recursion reaches: the stabilising one when Q sees every unstable mode. Empty if it diverges.
std::optional<Eigen::MatrixXd> doubling(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::MatrixXd& q,
                                        const Eigen::MatrixXd& r) {
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(a.rows(), a.cols());
  Eigen::MatrixXd ak = a;
  Eigen::MatrixXd gk = b * r.ldlt().solve(b.transpose());
  gk = (gk + gk.transpose()) / 2;
  Eigen::MatrixXd hk = q;
  for (int step = 0; step < max_doublings; ++step) {
    // I + G H is invertible: G and H are positive semi-definite, so G H has no negative eigenvalues.
    const Eigen::PartialPivLU<Eigen::MatrixXd> w{identity + gk * hk};
    const Eigen::MatrixXd w_a = w.solve(ak);
    const Eigen::MatrixXd w_g = w.solve(gk);
    Eigen::MatrixXd h_next = hk + ak.transpose() * hk * w_a;
    h_next = (h_next + h_next.transpose()) / 2;
    gk += ak * w_g * ak.transpose();
    gk = (gk + gk.transpose()) / 2;
    ak = ak * w_a;
    if (!h_next.allFinite()) return std::nullopt;
    const double change = (h_next - hk).norm();
    hk = std::move(h_next);
    if (change <= converged * hk.norm()) return hk;
  }
  return std::nullopt;
}

// K = (R + B' S B)^-1 B' S A.
Eigen::MatrixXd gain_of(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::MatrixXd& r,
                        const Eigen::MatrixXd& s) {
  const Eigen::MatrixXd bs = b.transpose() * s;
  return (r + bs * b).ldlt().solve(bs * a);
}

double spectral_radius(const Eigen::MatrixXd& m) {
  return Eigen::EigenSolver<Eigen::MatrixXd>{m, false}.eigenvalues().cwiseAbs().maxCoeff();
}

// The cost of a stable closed loop F with stage weight W: S = sum over k of F'^k W F^k, summed by doubling.
std::optional<Eigen::MatrixXd> stein(const Eigen::MatrixXd& f, const Eigen::MatrixXd& w) {
  Eigen::MatrixXd sum = w;
  Eigen::MatrixXd power = f;
  for (int step = 0; step < max_doublings; ++step) {
    Eigen::MatrixXd next = sum + power.transpose() * sum * power;
    next = (next + next.transpose()) / 2;
    power = power * power;
    if (!next.allFinite()) return std::nullopt;
    const double change = (next - sum).norm();
    sum = std::move(next);
    if (change <= converged * sum.norm()) return sum;
  }
  return std::nullopt;
}

// The stabilising solution S of the DARE for (A, B, Q, R) whose sizes and weights have been checked, or the closest
// the methods get when none exists (the caller checks the closed loop).
Result<Eigen::MatrixXd> solve_dare(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::MatrixXd& q,
                                   const Eigen::MatrixXd& r, const Wording& words) {
  if (auto mode = unreachable_mode(a, b)) return Failure{words.not_stabilisable + eigenvalue_text(*mode)};
  auto solution = doubling(a, b, q, r);
  if (solution && spectral_radius(a - b * gain_of(a, b, r, *solution)) < unit_circle) return *solution;
  // Q leaves an unstable mode unweighted (the cheapest way to stabilise it is still to stabilise it, but the recursion
  // from S = 0 never learns that), or the doubling did not converge. Newton's method on the DARE (Hewer, 1971) walks
  // from any stabilising gain to the stabilising solution: start from the gain for Q + I, which weighs every mode.
  const double scale = q.norm() > 0 ? q.norm() : 1;
  auto start = doubling(a, b, q + scale * Eigen::MatrixXd::Identity(a.rows(), a.cols()), r);
  if (!start)
    return Failure{"the Riccati equation did not converge in " + std::to_string(max_doublings) + " doublings"};
  Eigen::MatrixXd s = std::move(start).value();
  Eigen::MatrixXd k = gain_of(a, b, r, s);
  for (int step = 0; step < max_newton_steps; ++step) {
    const Eigen::MatrixXd closed = a - b * k;
    if (spectral_radius(closed) >= unit_circle) break;  // creeping onto the circle: the caller says why
    auto cost = stein(closed, q + k.transpose() * r * k);
    if (!cost) break;
    const double change = (cost.value() - s).norm();
    s = std::move(cost).value();
    k = gain_of(a, b, r, s);
    if (change <= converged * s.norm()) break;
  }
  return s;
}

std::optional<Failure> check_closed_loop(const Eigen::VectorXcd& eigenvalues, const Wording& words) {
  if (eigenvalues.size() > 0 && std::abs(eigenvalues(0)) >= unit_circle) {
    return Failure{words.no_stabilising_solution + eigenvalue_text(eigenvalues(0))};
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> weight_problem(std::string_view name, const Eigen::MatrixXd& weight, bool definite) {
  const std::string named{name};
  if (weight.rows() != weight.cols() || weight.size() == 0) {
    return named + " must be square and not empty; it is " + size_text(weight);
  }
  if (!weight.allFinite()) return named + " must hold finite numbers";
  const double largest = weight.cwiseAbs().maxCoeff();
  if ((weight - weight.transpose()).cwiseAbs().maxCoeff() > 1e-12 * largest) return named + " must be symmetric";
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>{weight}.eigenvalues();
  const double least = eigenvalues.minCoeff();
  if (definite && least <= 0) {
    return named + " must be positive definite; it has the eigenvalue " + number_text(least);
  }
  if (least < -1e-12 * largest) {
    return named + " must be positive semi-definite; it has the eigenvalue " + number_text(least);
  }
  return std::nullopt;
}

Eigen::VectorXcd sorted_eigenvalues(const Eigen::MatrixXd& square) {
  Eigen::VectorXcd values = Eigen::EigenSolver<Eigen::MatrixXd>{square, false}.eigenvalues();
  std::sort(values.begin(), values.end(), [](std::complex<double> x, std::complex<double> y) {
    if (std::abs(x) != std::abs(y)) return std::abs(x) > std::abs(y);
    if (x.real() != y.real()) return x.real() > y.real();
    return x.imag() > y.imag();
  });
  return values;
}

Result<RegulatorDesign> dlqr(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::MatrixXd& q,
                             const Eigen::MatrixXd& r) {
  const Eigen::Index n = a.rows();
  const Eigen::Index m = b.cols();
  if (n == 0 || a.cols() != n) return Failure{"A must be square and not empty; it is " + size_text(a)};
  if (b.rows() != n || m == 0) {
    return Failure{"B must be " + std::to_string(n) + "xm (a row per state, a column per input); it is " +
                   size_text(b)};
  }
  if (q.rows() != n || q.cols() != n) return Failure{"Q must be " + size_text(a) + " like A; it is " + size_text(q)};
  if (r.rows() != m || r.cols() != m) {
    return Failure{"R must be " + std::to_string(m) + "x" + std::to_string(m) +
                   " (one row and column per input); it is " + size_text(r)};
  }
  if (!a.allFinite() || !b.allFinite() || !q.allFinite() || !r.allFinite()) {
    return Failure{"A, B, Q and R must hold finite numbers"};
  }
  const Wording words{
      .not_stabilisable = "(A, B) is not stabilisable: the inputs cannot move the mode at eigenvalue ",
      .no_stabilising_solution =
          "no stabilising gain exists: Q does not weigh the mode on the unit circle at eigenvalue ",
  };
  if (auto problem = check_weights(q, r)) return *problem;
  auto solution = solve_dare(a, b, q, r, words);
  if (!solution) return Failure{solution.error()};
  RegulatorDesign design;
  design.riccati = std::move(solution).value();
  design.gain = gain_of(a, b, r, design.riccati);
  design.closed_loop_eigenvalues = sorted_eigenvalues(a - b * design.gain);
  if (auto problem = check_closed_loop(design.closed_loop_eigenvalues, words)) return *problem;
  return design;
}

Result<KalmanDesign> kalman_gain(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c, const Eigen::MatrixXd& g,
                                 const Eigen::MatrixXd& q, const Eigen::MatrixXd& r) {
  const Eigen::Index n = a.rows();
  if (n == 0 || a.cols() != n) return Failure{"A must be square and not empty; it is " + size_text(a)};
  if (c.cols() != n || c.rows() == 0) {
    return Failure{"C must be px" + std::to_string(n) + " (a row per output, a column per state); it is " +
                   size_text(c)};
  }
  if (g.rows() != n || g.cols() == 0) {
    return Failure{"G must be " + std::to_string(n) + "xw (a row per state, a column per noise input); it is " +
                   size_text(g)};
  }
  if (q.rows() != g.cols() || q.cols() != g.cols()) {
    return Failure{"Q must be " + std::to_string(g.cols()) + "x" + std::to_string(g.cols()) +
                   " (one row and column per noise input, a column of G); it is " + size_text(q)};
  }
  if (r.rows() != c.rows() || r.cols() != c.rows()) {
    return Failure{"R must be " + std::to_string(c.rows()) + "x" + std::to_string(c.rows()) +
                   " (one row and column per output, a row of C); it is " + size_text(r)};
  }
  if (!a.allFinite() || !c.allFinite() || !g.allFinite() || !q.allFinite() || !r.allFinite()) {
    return Failure{"A, C, G, Q and R must hold finite numbers"};
  }
  const Wording words{
      .not_stabilisable = "(A, C) is not detectable: the outputs do not see the mode at eigenvalue ",
      .no_stabilising_solution =
          "no stable filter exists: the process noise G Q G' does not excite the mode on the unit circle at "
          "eigenvalue ",
  };
  if (auto problem = check_weights(q, r)) return *problem;
  const Eigen::MatrixXd process = g * q * g.transpose();
  auto solution = solve_dare(a.transpose(), c.transpose(), (process + process.transpose()) / 2, r, words);
  if (!solution) return Failure{solution.error()};
  KalmanDesign design;
  design.predicted_covariance = std::move(solution).value();
  const Eigen::MatrixXd& p = design.predicted_covariance;
  // K = P C' (C P C' + R)^-1, computed as the transpose of a solve with the symmetric innovation covariance.
  const Eigen::MatrixXd innovation = c * p * c.transpose() + r;
  design.gain = innovation.ldlt().solve(c * p).transpose();
  const Eigen::MatrixXd correction = Eigen::MatrixXd::Identity(n, n) - design.gain * c;
  const Eigen::MatrixXd filtered = correction * p;
  design.filtered_covariance = (filtered + filtered.transpose()) / 2;
  design.estimator_eigenvalues = sorted_eigenvalues(a * correction);
  if (auto problem = check_closed_loop(design.estimator_eigenvalues, words)) return *problem;
  return design;
}

}  // namespace duet::control
