#pragma once
// The thesis' MATLAB function of the ultrasonic subsystem (figure 5.49): TIM5 captures ECHO0 on both edges, and the
// counter restarts at every capture, so of each two captures the first (the rising edge) ends the pause before the
// echo and the second (the falling edge) is the echo's length. This passes every second count and holds it between.
// Freestanding: the firmware and duet sim compile this same function.

template <typename In, typename Out, typename State, typename Parameters>
void every_second(const In& in, Out& out, State& state, const Parameters& /*parameters*/) {
  state.second = !state.second;
  if (!state.second) state.held = in.count;  // the second of a pair: the falling edge
  out.length = state.held;
}
