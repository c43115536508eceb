#pragma once
// The self-balancing robot (thesis section 5.8) linearised about upright, with its two DC motors.

#include <optional>

#include "duet/control/discretise.hpp"

namespace duet::control {

// SI units throughout. The masses and lengths are the thesis'; what the thesis does not give (the wheels' and rotors'
// inertia, the motor constants) defaults to what the simulated robot (src/plant/balbot, BalbotParameters) chose when
// this was written: keep the two in step, or pass the plant's numbers.
struct BalbotParameters {
  double wheel_mass = 0.090;               // m_w, kg: both wheels
  double body_mass = 0.706;                // m_p, kg
  double axle_to_centre_of_mass = 0.1485;  // l, m
  double body_depth = 0.070;               // b, m: the cuboid of eq. 5.17
  // J_x, kg m^2, about the body's centre of mass; unset: the cuboid of eq. 5.17, m_p (b^2 + h^2) / 12 with h = 2 l.
  std::optional<double> body_inertia;
  double wheel_radius = 0.031;                         // r_w, m
  double wheel_inertia = 0.5 * 0.090 * 0.031 * 0.031;  // J_w, kg m^2: both wheels as solid discs about the axle
  double gravity = 9.81;                               // g, m/s^2
  // Drive: `motors` identical DC motors in parallel, each through a gearbox of `gear_ratio` (motor turns per wheel
  // turn); armature inductance neglected (its time constant is far below the 1 ms sample time).
  int motors = 2;
  double gear_ratio = 30;
  double torque_constant = 8.334e-3;    // k_t, N m/A at the motor shaft
  double back_emf_constant = 8.334e-3;  // k_e, V s/rad at the motor shaft (equals k_t in SI)
  double armature_resistance = 4.0;     // R, ohm: winding and driver switches
  double rotor_inertia = 4.0e-7;        // one motor's rotor and gears at the motor shaft, kg m^2
  double motor_friction = 1.0e-6;       // viscous, at the motor shaft, N m s/rad
  // Volts at the motor per unit of the model's input: 1 for an input in volts; the battery voltage for an input that
  // is the PWM duty as a fraction (-1..1).
  double volts_per_input = 1;
};

// J_x as used: the given one, or the cuboid's of eq. 5.17.
[[nodiscard]] double body_inertia(const BalbotParameters& robot);

// x' = A x + B u with x = [x_w (m), v = x_w' (m/s), theta (rad), theta' (rad/s)] and u the motor voltage (times
// volts_per_input). theta > 0 is the body behind the axle, x_p = x_w - l sin(theta) (eq. 5.20a); u > 0 drives the robot
// forward (x_w grows) and, by the motors' reaction, tilts the body backwards (theta grows).
// Thesis eqs. 5.26 and 5.29 linearised (5.33), with the wheels' and rotors' inertia and the motors' torque tau (summed
// over the motors, at the wheels) acting through the ground on x_w and, as reaction, on the body:
//   M_xx x_w'' + M_xt theta'' = tau / r_w
//   M_xt x_w'' + M_tt theta'' = m_p g l theta + tau
// with J_r = motors gear_ratio^2 rotor_inertia, M_xx = m_w + m_p + (J_w + J_r) / r_w^2, M_xt = J_r / r_w - m_p l,
// M_tt = J_x + m_p l^2 + J_r; the motors turn with the wheels relative to the body, w = v / r_w + theta', so
//   tau = motors gear_ratio (k_t (volts_per_input u - gear_ratio k_e w) / R - gear_ratio motor_friction w).
// Preconditions, checked: positive masses, lengths, ratio and resistance; inertias and motor constants not negative.
[[nodiscard]] Result<ContinuousModel> linearise_balbot(const BalbotParameters& robot = {});

}  // namespace duet::control
