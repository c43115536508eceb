#pragma once
// The robot's tilt PID (the thesis' controller: e = target - Kalman-filtered tilt in degrees, parallel PID with
// derivative filter, output the PWM duty) closed around the robot's linear model in discrete time, its closed-loop
// modes, and gains chosen by the slowest mode they can move (src/control/README.md, "The tilt PID").

#include <Eigen/Dense>

#include <complex>
#include <optional>

#include "duet/control/balbot_model.hpp"
#include "duet/support/result.hpp"

namespace duet::control {

// The loop around the PID: the robot (its input the duty, volts_per_input the battery voltage), how late the duty
// acts and what the sensors read, and the Kalman filter in front of the PID.
struct PidLoopSpec {
  BalbotParameters robot;
  double period_s = 0.001;
  // From the step that computes the duty to the duty acting on the motors (the PWM's interrupt comes at most a
  // period later): the last step's duty acts for this long into each period. 0 <= input_delay_s < period_s.
  double input_delay_s = 0;
  // The accelerometer's height above the axle: it reads the tilt plus the acceleration there over g,
  // atan(a_x / a_z) = theta + (x_w'' - h theta'') / g to first order. Negative: a sensor that reads the tilt only.
  double sensor_height_m = -1;
  // The tilt filter (the model's KalmanFilter on [tilt (deg), rate (deg/s)], both measured): A = [[1, Ts], [0, 1]],
  // C = I, G = [Ts, 1]', process noise q ((deg/s)^2), measurement noise r (2x2) — in its steady state.
  double kalman_q = 9;
  Eigen::Matrix2d kalman_r{{0.8, 0}, {0, 330e-6}};
};

// P (duty per degree), I (per degree second), D (seconds per degree), N (1/s): C(z) = P + I Ts / (z - 1) +
// D N / (1 + N Ts / (z - 1)), forward Euler, on the error in degrees.
struct PidLoopGains {
  double p;
  double i;
  double d;
  double n;
};

// The loop's open part, ready to close with any gains: the robot without its position (nothing depends on it),
// [v, theta, theta'], the duty of the last step, and the Kalman filter's steady-state gain.
class PidLoop {
 public:
  // Fails with a message when the robot's parameters, the period, the delay or the filter's noises are not valid.
  [[nodiscard]] static Result<PidLoop> make(const PidLoopSpec& spec);

  // The closed loop's state matrix, x[k+1] = A x[k], over x = [v (m/s), theta (rad), theta' (rad/s), the duty acting
  // first in the period, the filter's predicted tilt (deg) and rate (deg/s), the integrator, the derivative filter].
  [[nodiscard]] Eigen::MatrixXd closed_loop(const PidLoopGains& gains) const;

  // A mode of the closed loop that no gain moves: rolling at a steady speed, balanced, with the integrator holding the
  // duty that keeps the wheels turning at that speed. An eigenvector of closed_loop() at 1 for every gain with I != 0.
  [[nodiscard]] Eigen::VectorXd rolling_mode() const;

  // The closed loop's other eigenvalues (rolling_mode() deflated), largest magnitude first.
  [[nodiscard]] Eigen::VectorXcd moving_eigenvalues(const PidLoopGains& gains) const;

  [[nodiscard]] const Eigen::Matrix2d& kalman_gain() const { return kalman_gain_; }
  [[nodiscard]] double period_s() const { return period_s_; }
  [[nodiscard]] double filter_slowest() const { return filter_slowest_; }

 private:
  PidLoop() = default;

  double period_s_ = 0;
  Eigen::Matrix3d ad_;                    // over a whole period
  Eigen::Vector3d b_late_;                // the new duty, from input_delay_s to the period's end
  Eigen::Vector3d b_early_;               // the last step's duty, until input_delay_s
  Eigen::Matrix<double, 2, 4> measured_;  // [tilt (deg), rate (deg/s)] from [v, theta, theta', duty acting]
  Eigen::Matrix2d kalman_gain_;
  double filter_slowest_ = 0;
  double rolling_duty_per_speed_ = 0;  // the duty that keeps the wheels turning at 1 m/s, balanced
};

// How to choose the gains: the slowest mode's magnitude is minimised over P, I and D (N given), the search kept to
// gains a real loop tolerates.
struct PidCriterion {
  double n = 28.234;  // the derivative filter's coefficient, 1/s (the thesis')
  // Every moving mode at least this damped, as a continuous-time damping ratio (the mode's z = e^(s Ts)).
  double minimum_damping = 0.5;
  // The most duty per degree the PID may give a sudden change of the tilt: P + D N, its gain at high frequencies.
  double maximum_high_frequency_gain = 1;
};

// What the criterion sees in a loop closed with `gains`.
struct PidEvaluation {
  Eigen::VectorXcd moving_eigenvalues;  // the closed loop's without the rolling mode, largest magnitude first
  // The filter's mode, left out of the criterion: the largest moving eigenvalue when it lies between the filter's
  // own slowest eigenvalue and 1.
  std::optional<std::complex<double>> filter_mode;
  double slowest_time_constant_s;  // -Ts / ln |z| of the slowest mode counted
  bool within_limits;              // stable, every counted mode damped enough, P + D N small enough
  double cost;                     // what design_pid minimises
};

[[nodiscard]] PidEvaluation evaluate_pid(const PidLoop& loop, const PidCriterion& criterion, const PidLoopGains& gains);

struct PidDesign {
  PidLoopGains gains;
  PidEvaluation evaluation;
};

// Minimises the slowest moving mode's magnitude under the criterion's limits: a grid over P, I and D (logarithmic,
// positive gains), then Nelder and Mead's simplex from the best point of the grid. Fails when no gains on the grid
// stabilise the loop within the limits.
[[nodiscard]] Result<PidDesign> design_pid(const PidLoop& loop, const PidCriterion& criterion);

}  // namespace duet::control
