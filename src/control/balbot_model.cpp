#include "duet/control/balbot_model.hpp"

#include <cmath>
#include <string>

#include "duet/control/parameter_text.hpp"

namespace duet::control {

double body_inertia(const BalbotParameters& robot) {
  if (robot.body_inertia) return *robot.body_inertia;
  const double height = 2 * robot.axle_to_centre_of_mass;
  return robot.body_mass * (robot.body_depth * robot.body_depth + height * height) / 12;
}

Result<ContinuousModel> linearise_balbot(const BalbotParameters& robot) {
  const struct {
    const char* name;
    double value;
  } positive[] = {{"wheel_mass", robot.wheel_mass},
                  {"body_mass", robot.body_mass},
                  {"axle_to_centre_of_mass", robot.axle_to_centre_of_mass},
                  {"body_inertia", body_inertia(robot)},
                  {"wheel_radius", robot.wheel_radius},
                  {"gravity", robot.gravity},
                  {"gear_ratio", robot.gear_ratio},
                  {"armature_resistance", robot.armature_resistance}};
  for (const auto& [name, value] : positive) {
    if (!std::isfinite(value) || value <= 0) {
      return Failure{std::string{name} + " must be a positive number; it is " + number_text(value)};
    }
  }
  const struct {
    const char* name;
    double value;
  } not_negative[] = {{"body_depth", robot.body_depth},           {"wheel_inertia", robot.wheel_inertia},
                      {"torque_constant", robot.torque_constant}, {"back_emf_constant", robot.back_emf_constant},
                      {"rotor_inertia", robot.rotor_inertia},     {"motor_friction", robot.motor_friction}};
  for (const auto& [name, value] : not_negative) {
    if (!std::isfinite(value) || value < 0) {
      return Failure{std::string{name} + " must be a number, 0 or more; it is " + number_text(value)};
    }
  }
  if (robot.motors < 1) return Failure{"motors must be 1 or more; it is " + std::to_string(robot.motors)};
  if (!std::isfinite(robot.volts_per_input)) return Failure{"volts_per_input must be a number"};

  const double r_w = robot.wheel_radius;
  const double l = robot.axle_to_centre_of_mass;
  const double n = robot.gear_ratio;
  const double rotors = robot.motors * n * n * robot.rotor_inertia;  // J_r: the rotors as seen from the wheels
  const double m_xx = robot.wheel_mass + robot.body_mass + (robot.wheel_inertia + rotors) / (r_w * r_w);
  const double m_xt = rotors / r_w - robot.body_mass * l;
  const double m_tt = body_inertia(robot) + robot.body_mass * l * l + rotors;
  const double gravity_torque = robot.body_mass * robot.gravity * l;  // m_p g l, per radian of tilt
  // [[M_xx, M_xt], [M_xt, M_tt]] [x_w''; theta''] = [tau / r_w; m_p g l theta + tau]; the mass matrix's inverse is
  // [[M_tt, -M_xt], [-M_xt, M_xx]] / det, det > 0 (the kinetic energy is positive).
  const double det = m_xx * m_tt - m_xt * m_xt;
  // tau = drive u - drag w, w = v / r_w + theta' (the motors' rotation relative to the body, at the wheels).
  const double drive = robot.motors * n * robot.torque_constant * robot.volts_per_input / robot.armature_resistance;
  const double drag =
      robot.motors * n * n *
      (robot.torque_constant * robot.back_emf_constant / robot.armature_resistance + robot.motor_friction);
  // How tau reaches each acceleration.
  const double tau_to_x = (m_tt / r_w - m_xt) / det;
  const double tau_to_theta = (m_xx - m_xt / r_w) / det;

  ContinuousModel model{Eigen::MatrixXd::Zero(4, 4), Eigen::MatrixXd::Zero(4, 1)};
  Eigen::MatrixXd& a = model.a;
  a(0, 1) = 1;
  a(2, 3) = 1;
  a(1, 1) = -tau_to_x * drag / r_w;
  a(1, 2) = -m_xt * gravity_torque / det;
  a(1, 3) = -tau_to_x * drag;
  a(3, 1) = -tau_to_theta * drag / r_w;
  a(3, 2) = m_xx * gravity_torque / det;
  a(3, 3) = -tau_to_theta * drag;
  model.b(1, 0) = tau_to_x * drive;
  model.b(3, 0) = tau_to_theta * drive;
  return model;
}

}  // namespace duet::control
