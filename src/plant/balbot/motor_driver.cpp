#include "motor_driver.hpp"

#include <algorithm>

namespace duet::plant::balbot {

DriverOutputs tb6612fng(const DriverInputs& in, double forward_disturbance, bool clockwise_is_forward) {
  DriverOutputs out;
  if (!in.standby_high) return out;  // standby: outputs off whatever the inputs
  if (in.in1 && in.in2) {            // short brake: both outputs low, the winding shorted
    out = {MotorMode::short_brake, PinLevel::low, PinLevel::low, {.connected = true, .drive = 0}};
    return out;
  }
  if (!in.in1 && !in.in2) {  // stop: outputs off (the table lists PWM high; with PWM low nothing is switched on either)
    out.mode = MotorMode::stop;
    return out;
  }
  // A direction: IN1 high = clockwise. PWM high drives, PWM low short-brakes; on average the winding sees
  // duty * V_bat, shorted for the rest of the period.
  const double duty = std::clamp(in.duty, 0.0, 1.0);
  const double clockwise_disturbance = clockwise_is_forward ? forward_disturbance : -forward_disturbance;
  const double drive = std::clamp((in.in1 ? duty : -duty) + clockwise_disturbance, -1.0, 1.0);
  out.drive = {.connected = true, .drive = drive};
  if (drive > 0) {
    out.mode = MotorMode::clockwise;
    out.out1 = PinLevel::high;
    out.out2 = PinLevel::low;
  } else if (drive < 0) {
    out.mode = MotorMode::counter_clockwise;
    out.out1 = PinLevel::low;
    out.out2 = PinLevel::high;
  } else {
    out.mode = MotorMode::short_brake;
    out.out1 = PinLevel::low;
    out.out2 = PinLevel::low;
  }
  return out;
}

}  // namespace duet::plant::balbot
