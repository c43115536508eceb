#include "mechanics.hpp"

#include <cmath>

#include "fast_math.hpp"

namespace duet::plant::balbot {
namespace {

// Both motors' rotors at the wheels: each turns gear_ratio times faster than the wheel relative to the body.
double rotors_at_wheels(const BalbotParameters& p) { return 2 * p.gear_ratio * p.gear_ratio * p.rotor_inertia_kg_m2; }

}  // namespace

Mechanics::Mechanics(const BalbotParameters& p, BalbotRig rig, double battery_open_circuit_v)
    : rig_(rig),
      inverse_wheel_radius_(1 / p.wheel_radius_m),
      body_mass_(p.body_mass_kg),
      lever_(p.axle_to_centre_of_mass_m),
      gravity_(p.gravity_m_s2),
      mass_xx_(p.wheel_mass_kg + p.body_mass_kg +
               (p.wheel_inertia_kg_m2 + rotors_at_wheels(p)) / (p.wheel_radius_m * p.wheel_radius_m)),
      mass_tt_(p.body_inertia_kg_m2() + p.body_mass_kg * p.axle_to_centre_of_mass_m * p.axle_to_centre_of_mass_m +
               rotors_at_wheels(p)),
      mass_xt_rotor_(rotors_at_wheels(p) / p.wheel_radius_m),
      held_gain_(p.wheel_radius_m / (p.wheel_inertia_kg_m2 + rotors_at_wheels(p))),
      floor_tilt_(std::acos(-p.wheel_radius_m / p.body_height_m)),
      floor_stiffness_(p.floor_stiffness_n_m_rad),
      floor_damping_(p.floor_damping_n_m_s_rad),
      gear_ratio_(p.gear_ratio),
      motor_constant_(p.motor_constant_v_s_rad),
      conductance_(1 / p.armature_resistance_ohm),
      friction_(p.motor_friction_n_m_s_rad),
      battery_v_(battery_open_circuit_v),
      battery_to_winding_(p.battery_resistance_ohm / p.armature_resistance_ohm) {}

Mechanics::Torque Mechanics::torque(double wheel_rate, const Drive& drive) const {
  // The left motor turns clockwise when the wheels turn forward, the right one (mirrored) counter-clockwise.
  Torque out;
  Electrical& e = out.electrical;
  e.left_rad_s = gear_ratio_ * wheel_rate;
  e.right_rad_s = -e.left_rad_s;
  // Average-voltage PWM: a connected winding sees drive * V_bat (shorted in the off-phase), i = (V - k w) / R, and
  // the battery delivers drive * i for each. V_bat = V_oc - R_bat * sum(drive * i) is linear in V_bat: solved exactly.
  const double ul = drive.left.connected ? drive.left.drive : 0.0;
  const double ur = drive.right.connected ? drive.right.drive : 0.0;
  const double k = motor_constant_;
  e.battery_v = (battery_v_ + battery_to_winding_ * k * (ul * e.left_rad_s + ur * e.right_rad_s)) /
                (1 + battery_to_winding_ * (ul * ul + ur * ur));
  e.left_v = drive.left.connected ? ul * e.battery_v : 0.0;
  e.right_v = drive.right.connected ? ur * e.battery_v : 0.0;
  e.left_a = drive.left.connected ? (e.left_v - k * e.left_rad_s) * conductance_ : 0.0;
  e.right_a = drive.right.connected ? (e.right_v - k * e.right_rad_s) * conductance_ : 0.0;
  e.battery_a = ul * e.left_a + ur * e.right_a;
  const double left = k * e.left_a - friction_ * e.left_rad_s;
  const double right = k * e.right_a - friction_ * e.right_rad_s;
  out.wheel = gear_ratio_ * (left - right);
  return out;
}

Drive Mechanics::prepared(Drive drive) const {
  drive.torque_at_rest = torque(0, drive).wheel;
  drive.torque_per_rate = torque(1, drive).wheel - drive.torque_at_rest;
  return drive;
}

Derivative Mechanics::derivative(const MechanicalState& s, const Drive& drive) const {
  Derivative d{.v = s.v, .omega = s.omega};
  if (drive.held) return {};  // at rest, and kept there
  switch (rig_) {
    case BalbotRig::wheels_driven: return d;
    case BalbotRig::held_in_air:
      d.omega = 0;
      d.a = (drive.torque_at_rest + drive.torque_per_rate * s.v * inverse_wheel_radius_) * held_gain_;
      return d;
    case BalbotRig::on_ground: break;
  }
  const double wheel = drive.torque_at_rest + drive.torque_per_rate * wheel_rate(s);
  const auto [sine, cosine] = sine_cosine(s.theta);
  const double ml = body_mass_ * lever_;
  // Lagrange's equations in (x, theta): M(theta) [a, alpha] = Q - c. The wheel torque acts on x through the ground
  // (wheel / r) and, as the reaction of the motors fixed to the body, on theta; the push acts at the centre of mass.
  const double mass_xt = mass_xt_rotor_ - ml * cosine;
  const double force_x = wheel * inverse_wheel_radius_ + drive.push_force_n - ml * sine * s.omega * s.omega;
  double force_t = wheel - drive.push_force_n * lever_ * cosine + ml * gravity_ * sine;
  const double into_floor = std::abs(s.theta) - floor_tilt_;
  if (into_floor > 0) force_t -= std::copysign(floor_stiffness_ * into_floor, s.theta) + floor_damping_ * s.omega;
  const double inverse_determinant = 1 / (mass_xx_ * mass_tt_ - mass_xt * mass_xt);
  d.a = (force_x * mass_tt_ - mass_xt * force_t) * inverse_determinant;
  d.alpha = (mass_xx_ * force_t - mass_xt * force_x) * inverse_determinant;
  return d;
}

Electrical Mechanics::electrical(const MechanicalState& s, const Drive& drive) const {
  return torque(wheel_rate(s), drive).electrical;  // held, the body does not turn: omega is 0
}

MechanicalState Mechanics::step(const MechanicalState& s, const Derivative& k1, const Drive& drive, double h) const {
  // The explicit midpoint rule (second-order Runge-Kutta): one more evaluation of the equations of motion than Euler,
  // two fewer than RK4, which made the robot a third of a simulated minute's cost. At steps of at most 1 ms against
  // the robot's fastest motion (the tilt's 7.7/s) that is accurate enough: through a whole fall energy drifts by
  // 1.1e-6 of itself, and over the disturbed minute (scenarios/disturbed.yaml) the tilt differs from RK4's by at most
  // 0.03 degrees (during the 5-degree push), the position by 0.6 mm.
  const MechanicalState half{s.x + h / 2 * k1.v, s.theta + h / 2 * k1.omega, s.v + h / 2 * k1.a,
                             s.omega + h / 2 * k1.alpha};
  const Derivative k2 = derivative(half, drive);
  return {s.x + h * k2.v, s.theta + h * k2.omega, s.v + h * k2.a, s.omega + h * k2.alpha};
}

double Mechanics::energy(const MechanicalState& s) const {
  const double ml = body_mass_ * lever_;
  const double cosine = sine_cosine(s.theta).cosine;
  const double mass_xt = mass_xt_rotor_ - ml * cosine;
  return 0.5 * mass_xx_ * s.v * s.v + mass_xt * s.v * s.omega + 0.5 * mass_tt_ * s.omega * s.omega +
         ml * gravity_ * cosine;
}

}  // namespace duet::plant::balbot

namespace duet::plant {

double balbot_tilt_growth_rate_per_s(const BalbotParameters& p) {
  // Linearised about theta = 0 with no torque: mass_xx a + mass_xt alpha = 0, mass_xt a + mass_tt alpha = m l g theta.
  const double rotors = 2 * p.gear_ratio * p.gear_ratio * p.rotor_inertia_kg_m2;
  const double r = p.wheel_radius_m;
  const double mass_xx = p.wheel_mass_kg + p.body_mass_kg + (p.wheel_inertia_kg_m2 + rotors) / (r * r);
  const double ml = p.body_mass_kg * p.axle_to_centre_of_mass_m;
  const double mass_tt = p.body_inertia_kg_m2() + ml * p.axle_to_centre_of_mass_m + rotors;
  const double mass_xt = rotors / r - ml;
  return std::sqrt(ml * p.gravity_m_s2 / (mass_tt - mass_xt * mass_xt / mass_xx));
}

}  // namespace duet::plant
