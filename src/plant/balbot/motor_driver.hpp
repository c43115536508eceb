#pragma once
// The TB6612FNG's truth table (thesis table 5.8) for one motor, and what it makes of the terminals.

#include "duet/plant/balbot/balbot_truth.hpp"
#include "mechanics.hpp"

namespace duet::plant::balbot {

struct DriverInputs {
  bool standby_high = false;  // STBY: high = operating
  bool in1 = false;
  bool in2 = false;
  double duty = 0;  // PWM duty fraction, 0..1
};

struct DriverOutputs {
  MotorMode mode = MotorMode::standby;
  PinLevel out1 = PinLevel::off;  // during the PWM's on-phase
  PinLevel out2 = PinLevel::off;
  MotorDrive drive;
};

// `forward_disturbance` (a duty fraction, + forward) is added to the signed duty while IN1 and IN2 select a
// direction, as if the controller's output had carried it (the thesis adds z1 before the motor logic);
// `clockwise_is_forward` tells which way this motor is mounted.
[[nodiscard]] DriverOutputs tb6612fng(const DriverInputs& in, double forward_disturbance, bool clockwise_is_forward);

}  // namespace duet::plant::balbot
