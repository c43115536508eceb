#include "duet/control/pid_design.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <utility>

#include "duet/control/discretise.hpp"
#include "duet/control/parameter_text.hpp"
#include "duet/control/riccati.hpp"

namespace duet::control {
namespace {

constexpr double degrees_per_radian = 180 / std::numbers::pi;
constexpr Eigen::Index states = 8;  // v, theta, theta', duty acting, filter's tilt and rate, integrator, filter

}  // namespace

Result<PidLoop> PidLoop::make(const PidLoopSpec& spec) {
  if (!std::isfinite(spec.period_s) || spec.period_s <= 0) {
    return Failure{"period_s must be a positive number of seconds; it is " + number_text(spec.period_s)};
  }
  if (!std::isfinite(spec.input_delay_s) || spec.input_delay_s < 0 || spec.input_delay_s >= spec.period_s) {
    return Failure{"input_delay_s must be at least 0 and less than the period (" + number_text(spec.period_s) +
                   " s); it is " + number_text(spec.input_delay_s)};
  }
  if (!std::isfinite(spec.sensor_height_m)) return Failure{"sensor_height_m must be a number"};
  auto robot = linearise_balbot(spec.robot);
  if (!robot) return Failure{"balbot: " + robot.error()};
  // Nothing in the robot depends on where it is: drop the position (row and column 0).
  const Eigen::Matrix3d a = robot.value().a.bottomRightCorner(3, 3);
  const Eigen::Vector3d b = robot.value().b.bottomRows(3);
  if (b(0) == 0) return Failure{"balbot: the duty does not drive the wheels (torque_constant or volts_per_input is 0)"};

  PidLoop loop;
  loop.period_s_ = spec.period_s;
  const double late_s = spec.period_s - spec.input_delay_s;
  auto whole = c2d(a, b, spec.period_s);
  auto late = c2d(a, b, late_s);
  if (!whole || !late) return Failure{whole ? late.error() : whole.error()};
  loop.ad_ = whole.value().ad;
  loop.b_late_ = late.value().bd;
  loop.b_early_.setZero();
  if (spec.input_delay_s > 0) {
    auto early = c2d(a, b, spec.input_delay_s);
    if (!early) return Failure{early.error()};
    loop.b_early_ = late.value().ad * early.value().bd;  // acts first, then moves with the robot to the period's end
  }

  // The sensors at a step: the last step's duty is still acting. [v', theta'', ...] = a x + b duty.
  loop.measured_.setZero();
  loop.measured_(0, 1) = degrees_per_radian;
  if (spec.sensor_height_m >= 0) {
    const double g = spec.robot.gravity;
    const double h = spec.sensor_height_m;
    loop.measured_.block<1, 3>(0, 0) += degrees_per_radian * (a.row(0) - h * a.row(2)) / g;
    loop.measured_(0, 3) = degrees_per_radian * (b(0) - h * b(2)) / g;
  }
  loop.measured_(1, 2) = degrees_per_radian;

  const double ts = spec.period_s;
  const Eigen::Matrix2d filter_a{{1, ts}, {0, 1}};
  const Eigen::Vector2d filter_g{ts, 1};
  auto filter = control::kalman_gain(filter_a, Eigen::Matrix2d::Identity(), filter_g,
                                     Eigen::MatrixXd::Constant(1, 1, spec.kalman_q), spec.kalman_r);
  if (!filter) return Failure{"kalman: " + filter.error()};
  loop.kalman_gain_ = filter.value().gain;
  loop.filter_slowest_ = std::abs(filter.value().estimator_eigenvalues(0));
  // Balanced at a steady speed v the robot is at rest relative to the motors' torque balance: a (v e_v) + b duty = 0.
  loop.rolling_duty_per_speed_ = -a(0, 0) / b(0);
  return loop;
}

Eigen::MatrixXd PidLoop::closed_loop(const PidLoopGains& gains) const {
  const double ts = period_s_;
  const Eigen::Matrix2d filter_a{{1, ts}, {0, 1}};
  // The filter's estimate x[k|k] = (I - L) x[k|k-1] + L y[k], y = measured_ [v, theta, theta', duty acting].
  Eigen::Matrix<double, 2, states> estimate = Eigen::Matrix<double, 2, states>::Zero();
  estimate.leftCols<4>() = kalman_gain_ * measured_;
  estimate.block<2, 2>(0, 4) = Eigen::Matrix2d::Identity() - kalman_gain_;
  const Eigen::RowVectorXd error = -estimate.row(0);  // e = target - tilt; the target adds no mode
  Eigen::RowVectorXd integrator = Eigen::RowVectorXd::Zero(states);
  integrator(6) = 1;
  Eigen::RowVectorXd filter = Eigen::RowVectorXd::Zero(states);
  filter(7) = 1;
  const Eigen::RowVectorXd derivative = gains.n * (gains.d * error - filter);
  const Eigen::RowVectorXd duty = gains.p * error + integrator + derivative;

  Eigen::MatrixXd loop = Eigen::MatrixXd::Zero(states, states);
  loop.topLeftCorner<3, 3>() = ad_;
  loop.block<3, 1>(0, 3) = b_early_;
  loop.topRows<3>() += b_late_ * duty;
  loop.row(3) = duty;
  loop.middleRows<2>(4) = filter_a * estimate;
  loop.row(6) = integrator + gains.i * ts * error;
  loop.row(7) = filter + ts * derivative;
  return loop;
}

Eigen::VectorXd PidLoop::rolling_mode() const {
  Eigen::VectorXd mode = Eigen::VectorXd::Zero(states);
  mode(0) = 1;                        // 1 m/s
  mode(3) = rolling_duty_per_speed_;  // the duty that keeps it,
  mode(6) = rolling_duty_per_speed_;  // held by the integrator; the tilt, the estimate and the derivative are 0
  return mode;
}

Eigen::VectorXcd PidLoop::moving_eigenvalues(const PidLoopGains& gains) const {
  // A Householder reflection Q with Q e_1 along the rolling mode: Q' A Q = [[1, *], [0, A_rest]], and A_rest's
  // eigenvalues are A's others.
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>{rolling_mode()}.householderQ();
  const Eigen::MatrixXd similar = q.transpose() * closed_loop(gains) * q;
  return sorted_eigenvalues(similar.bottomRightCorner(states - 1, states - 1));
}

PidEvaluation evaluate_pid(const PidLoop& loop, const PidCriterion& criterion, const PidLoopGains& gains) {
  PidEvaluation result{loop.moving_eigenvalues(gains), std::nullopt, 0, false, 0};
  const Eigen::VectorXcd& modes = result.moving_eigenvalues;
  const double ts = loop.period_s();
  const double first = std::abs(modes(0));
  if (first >= loop.filter_slowest() && first < 1) result.filter_mode = modes(0);
  const Eigen::Index counted = result.filter_mode ? 1 : 0;  // the first counted mode
  result.slowest_time_constant_s = -ts / std::log(std::abs(modes(counted)));
  double shortfall = 0;
  for (Eigen::Index k = counted; k < modes.size(); ++k) {
    if (std::abs(modes(k)) < 1e-6) continue;  // gone within a step or two
    const std::complex<double> s = std::log(modes(k)) / ts;
    shortfall += std::max(0.0, criterion.minimum_damping + s.real() / std::abs(s));
  }
  const double excess = std::max(0.0, gains.p + gains.d * gains.n - criterion.maximum_high_frequency_gain);
  const bool stable = first < 1;
  result.within_limits = stable && shortfall == 0 && excess == 0;
  // The search's cost, lower is better: minus the slowest counted mode's decay rate (a few hundred per second at
  // most), and far more for a limit missed by a little.
  constexpr double penalty = 1e5;
  result.cost = std::log(std::abs(modes(counted))) / ts + penalty * (shortfall + excess + (stable ? 0 : 1));
  return result;
}

namespace {

using Point = Eigen::Vector3d;  // natural logarithms of P, I, D

PidLoopGains gains_at(const Point& point, double n) {
  return {std::exp(point(0)), std::exp(point(1)), std::exp(point(2)), n};
}

}  // namespace

Result<PidDesign> design_pid(const PidLoop& loop, const PidCriterion& criterion) {
  const auto cost = [&](const Point& point) {
    return evaluate_pid(loop, criterion, gains_at(point, criterion.n)).cost;
  };
  // The grid: P from 0.001 to 1 per degree, I from 0.001 to 100 per degree second, D from 1e-5 to 0.1 s per degree.
  constexpr int steps = 9;
  const Point low{std::log(1e-3), std::log(1e-3), std::log(1e-5)};
  const Point high{std::log(1.0), std::log(100.0), std::log(0.1)};
  Point best = low;
  double best_cost = cost(best);
  for (int k = 0; k < steps * steps * steps; ++k) {
    const int p = k / (steps * steps);  // the grid's indices: P, I, D
    const int i = k / steps % steps;
    const int d = k % steps;
    const Point index{static_cast<double>(p), static_cast<double>(i), static_cast<double>(d)};
    const Point point = low + (index / (steps - 1)).cwiseProduct(high - low);
    const double value = cost(point);
    if (value < best_cost) {
      best_cost = value;
      best = point;
    }
  }
  // Nelder-Mead from the best grid point, a simplex of a grid step's size.
  std::array<Point, 4> simplex{best, best, best, best};
  std::array<double, 4> values{};
  for (Eigen::Index axis = 0; axis < 3; ++axis) {
    simplex[static_cast<std::size_t>(axis) + 1](axis) += (high(axis) - low(axis)) / (steps - 1);
  }
  for (std::size_t k = 0; k < simplex.size(); ++k) values[k] = cost(simplex[k]);
  constexpr int iterations = 2000;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    std::array<std::size_t, 4> order{0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return values[x] < values[y]; });
    const std::size_t worst = order[3];
    if ((simplex[order[0]] - simplex[worst]).norm() < 1e-10) break;
    Point centroid = (simplex[order[0]] + simplex[order[1]] + simplex[order[2]]) / 3;
    const Point reflected = centroid + (centroid - simplex[worst]);
    const double reflected_value = cost(reflected);
    if (reflected_value < values[order[0]]) {
      const Point expanded = centroid + 2 * (centroid - simplex[worst]);
      const double expanded_value = cost(expanded);
      const bool expand = expanded_value < reflected_value;
      simplex[worst] = expand ? expanded : reflected;
      values[worst] = expand ? expanded_value : reflected_value;
    } else if (reflected_value < values[order[2]]) {
      simplex[worst] = reflected;
      values[worst] = reflected_value;
    } else {
      const Point contracted = centroid + 0.5 * (simplex[worst] - centroid);
      const double contracted_value = cost(contracted);
      if (contracted_value < values[worst]) {
        simplex[worst] = contracted;
        values[worst] = contracted_value;
      } else {  // shrink towards the best
        for (const std::size_t k : {order[1], order[2], order[3]}) {
          simplex[k] = simplex[order[0]] + 0.5 * (simplex[k] - simplex[order[0]]);
          values[k] = cost(simplex[k]);
        }
      }
    }
  }
  const auto index = static_cast<std::size_t>(std::min_element(values.begin(), values.end()) - values.begin());
  const PidLoopGains gains = gains_at(simplex[index], criterion.n);
  PidEvaluation evaluation = evaluate_pid(loop, criterion, gains);
  if (!evaluation.within_limits) {
    return Failure{
        "no gains balance the robot within the limits (damping at least " + number_text(criterion.minimum_damping) +
        ", P + D N at most " + number_text(criterion.maximum_high_frequency_gain) +
        " per degree): the best found, P = " + number_text(gains.p) + ", I = " + number_text(gains.i) +
        ", D = " + number_text(gains.d) + ", leaves modes at " + eigenvalues_text(evaluation.moving_eigenvalues)};
  }
  return PidDesign{gains, std::move(evaluation)};
}

}  // namespace duet::control
