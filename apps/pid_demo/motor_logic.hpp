#pragma once
// The pid_demo model's Code block (pid_demo.yaml, block motor_logic): the thesis' "motor logic", which turns the
// controller's duty and the safety stop into the levels of the TB6612FNG H-bridge's pins (its truth table, thesis
// table 5.8) and the PWM duty in percent:
//
//   stop                   STBY L, IN1 L, IN2 L, PWM 0      standby
//   duty > dead band       STBY H, IN1 H, IN2 L, PWM duty   clockwise
//   duty < -dead band      STBY H, IN1 L, IN2 H, PWM -duty  counter-clockwise
//   otherwise              STBY H, IN1 H, IN2 H, PWM 0      short brake
//
// It counts the reversals: how often the motor was driven in the other direction than the last time it was driven.
// Freestanding C++ (no library calls, no heap): the same function runs in duet sim, on the PC and in the firmware.
// duet gen declares the four structures from the model; the function is a template over them.

#include <cstdint>

template <typename Inputs, typename Outputs, typename State, typename Parameters>
void motor_logic(const Inputs& in, Outputs& out, State& state, const Parameters& parameters) {
  // The direction the duty asks for: 1 clockwise, -1 counter-clockwise, 0 inside the dead band.
  std::int8_t direction = 0;
  if (in.duty > parameters.dead_band) {
    direction = 1;
  } else if (in.duty < -parameters.dead_band) {
    direction = -1;
  }
  if (in.stop) direction = 0;
  out.stby = !in.stop;
  out.in1 = !in.stop && direction >= 0;
  out.in2 = !in.stop && direction <= 0;
  if (direction > 0) {
    out.pwm = in.duty * 100.0F;
  } else if (direction < 0) {
    out.pwm = in.duty * -100.0F;
  } else {
    out.pwm = 0.0F;
  }
  if (direction != 0) {
    if (state.heading != 0 && state.heading != direction) ++state.reversals;
    state.heading = direction;
  }
  out.reversals = state.reversals;
}
