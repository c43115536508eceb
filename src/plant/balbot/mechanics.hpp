#pragma once
// The robot's equations of motion (README.md, "Mechanics"): the axle position x and the body tilt theta, driven by
// the two motors' torques through rolling without slip, with the wheels' and rotors' inertia and the motors' reaction
// on the body. Everything here is a pure function of its arguments, so a run is the same bit for bit.

#include "duet/plant/balbot/balbot_parameters.hpp"
#include "duet/plant/balbot/balbot_scenario.hpp"

namespace duet::plant::balbot {

struct MechanicalState {
  double x = 0;      // axle position, m, +x forward
  double theta = 0;  // tilt, rad; the centre of mass is at x - l sin(theta)
  double v = 0;      // dx/dt
  double omega = 0;  // dtheta/dt
};

// d/dt of a MechanicalState.
struct Derivative {
  double v = 0;
  double omega = 0;
  double a = 0;      // d2x/dt2
  double alpha = 0;  // d2theta/dt2
};

// One motor's terminals as the driver connects them, constant between two events.
struct MotorDrive {
  bool connected = false;  // false: outputs off (stop, standby): no current
  double drive = 0;        // terminal voltage / battery voltage, + clockwise (0: shorted)
};

struct Drive {
  MotorDrive left;
  MotorDrive right;
  double push_force_n = 0;  // horizontal, at the centre of mass
  bool held = false;        // held still by hand: nothing moves
  // For a given drive the wheel torque is linear in the wheels' rate: Mechanics::prepared() works out the line once.
  double torque_at_rest = 0;   // N m
  double torque_per_rate = 0;  // N m per rad/s
};

struct Electrical {
  double battery_v = 0;
  double battery_a = 0;
  double left_v = 0, left_a = 0, left_rad_s = 0;  // + clockwise of each motor
  double right_v = 0, right_a = 0, right_rad_s = 0;
};

class Mechanics {
 public:
  Mechanics(const BalbotParameters& parameters, BalbotRig rig, double battery_open_circuit_v);

  // The drive with its torque line (derivative() and step() take only prepared drives).
  [[nodiscard]] Drive prepared(Drive drive) const;
  [[nodiscard]] Derivative derivative(const MechanicalState& s, const Drive& drive) const;
  [[nodiscard]] Electrical electrical(const MechanicalState& s, const Drive& drive) const;
  // One classical Runge-Kutta step of `h` seconds; `k1` is derivative(s, drive).
  [[nodiscard]] MechanicalState step(const MechanicalState& s, const Derivative& k1, const Drive& drive,
                                     double h) const;
  // Kinetic plus potential energy (J), conserved without friction and with the motors disconnected.
  [[nodiscard]] double energy(const MechanicalState& s) const;

  // The wheels' angle relative to the body (rad, + forward): what the gearboxes, motors and encoders turn.
  [[nodiscard]] double wheel_angle(const MechanicalState& s) const { return s.x * inverse_wheel_radius_ + s.theta; }
  [[nodiscard]] double wheel_rate(const MechanicalState& s) const { return s.v * inverse_wheel_radius_ + s.omega; }

 private:
  struct Torque {
    double wheel = 0;  // on the wheels relative to the body, + forward
    Electrical electrical;
  };
  [[nodiscard]] Torque torque(double wheel_rate, const Drive& drive) const;

  BalbotRig rig_;
  double inverse_wheel_radius_;
  double body_mass_;
  double lever_;  // l
  double gravity_;
  double mass_xx_;  // mass matrix: x-x, theta-theta, and the part of x-theta that does not depend on theta
  double mass_tt_;
  double mass_xt_rotor_;
  double held_gain_;   // r / (wheels' and rotors' inertia about the axle): torque to acceleration, held in the air
  double floor_tilt_;  // where the body's top touches the floor
  double floor_stiffness_;
  double floor_damping_;
  double gear_ratio_;
  double motor_constant_;
  double conductance_;  // 1 / armature resistance
  double friction_;
  double battery_v_;
  double battery_to_winding_;  // battery resistance / armature resistance
};

}  // namespace duet::plant::balbot
