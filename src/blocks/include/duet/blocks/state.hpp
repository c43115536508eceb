#pragma once
// Blocks with state (Simulink's discrete blocks), as plain aggregates: generated code puts them in its state struct,
// XCP reads their public members, and they start from aggregate initialisation, e.g. UnitDelay<float>{0.5F}.
//
// Each step of a model calls output() for every block first and update() afterwards, with the same inputs, so an
// output never sees its own step's update. Every formula is written below in the exact order it is evaluated, with the
// arithmetic of arithmetic.hpp; tests pin that order, because another order rounds differently and simulation and
// firmware would drift apart. period_s is the block's sample time in seconds. Not interrupt-safe: one task owns a
// block.

#include <cstdint>
#include <type_traits>

#include "duet/blocks/arithmetic.hpp"
#include "duet/blocks/element.hpp"
#include "duet/blocks/nonlinear.hpp"

namespace duet::blocks {

// y(k) = x(k); x(k+1) = u(k).
template <Element T>
struct UnitDelay {
  T state;

  [[nodiscard]] constexpr T output() const { return state; }
  constexpr void update(T u) { state = u; }
};

// Forward Euler, y(k) = x(k) (Simulink's Discrete-Time Integrator, forward Euler, with limits on the state):
//   x(k+1) = saturate(add(x(k), multiply(multiply(gain, period_s), u)), lower, upper)
template <Floating T>
struct DiscreteIntegrator {
  T state;

  [[nodiscard]] constexpr T output() const { return state; }
  constexpr void update(T u, T gain, T period_s, T lower, T upper) {
    state = saturate(add(state, multiply(multiply(gain, period_s), u)), lower, upper);
  }
  // Without limits: the same as limits of -infinity and +infinity, which saturate lets every value through.
  constexpr void update(T u, T gain, T period_s) { state = add(state, multiply(multiply(gain, period_s), u)); }
};

// Backward difference (Simulink's Discrete Derivative):
//   y(k) = divide(multiply(gain, subtract(u(k), u(k-1))), period_s)
// previous starts as the first input's expected value; with 0 the first output is a jump from 0.
template <Floating T>
struct DiscreteDerivative {
  T previous;

  [[nodiscard]] constexpr T output(T u, T gain, T period_s) const {
    return divide(multiply(gain, subtract(u, previous)), period_s);
  }
  constexpr void update(T u) { previous = u; }
};

// The derivative of DiscretePid on its own: gain * N / (1 + N * Ts / (z - 1)), a derivative through a first-order
// filter with coefficient N (1/s), forward Euler (Simulink's Discrete PID Controller with only D, or Discrete Filtered
// Derivative). filter starts as the filter's state (usually 0: the first output is n * gain * u):
//   y      = multiply(n, subtract(multiply(gain, u), filter))
//   filter = add(filter, multiply(period_s, y))
// exactly DiscretePid's derivative and filter, so both round alike.
template <Floating T>
struct FilteredDerivative {
  T filter;

  [[nodiscard]] constexpr T output(T u, T gain, T n) const { return multiply(n, subtract(multiply(gain, u), filter)); }
  constexpr void update(T u, T gain, T n, T period_s) { filter = add(filter, multiply(period_s, output(u, gain, n))); }
};

// Parallel PID gains: proportional, integral, derivative, derivative filter coefficient N (1/s) and the output limits.
template <Floating T>
struct PidGains {
  T p;
  T i;
  T d;
  T n;
  T lower;
  T upper;
};

// Simulink's parallel discrete PID with forward Euler for both the integrator and the derivative filter:
//   P + I * Ts / (z - 1) + D * N / (1 + N * Ts / (z - 1))
// with the output limited, rounded in the order of Simulink's block (the integral gain, then the integrator's Ts).
// update() has no anti-windup (the integrator keeps integrating while the output saturates):
//   derivative = multiply(n, subtract(multiply(d, error), filter))
//   y          = saturate(add(add(multiply(p, error), integrator), derivative), lower, upper)
//   filter     = add(filter, multiply(period_s, derivative))
//   integrator = add(integrator, multiply(period_s, multiply(i, error)))
// update_clamped() is Simulink's "clamping" anti-windup: it updates filter as above but leaves the integrator as it is
// in a step where integrating would drive the output further into saturation, that is where
//   unlimited = add(add(multiply(p, error), integrator), derivative)    (y before saturate)
//   increment = multiply(period_s, multiply(i, error))                  (what update() would add)
//   (unlimited > upper and increment > 0) or (unlimited < lower and increment < 0)
// The sign that counts is the integrator input's, compared with the sign of the excess unlimited - saturate(unlimited),
// as Simulink does; it is the error's sign for positive i and period_s. An output exactly at a limit has no excess: the
// integrator integrates. A NaN unlimited output or increment clamps nothing (every comparison is false).
// update() and update_clamped() need the gains and error that output() saw in the same step; they recompute the
// derivative from them.
// The overloads with `reset` are Simulink's external reset, level-triggered: in a step whose reset is true the PID
// is at rest, integrator and filter 0, both when it computes its output and after its update, so the first step
// without reset starts from rest (the output of a step in reset is P e + N D e, limited).
template <Floating T>
struct DiscretePid {
  T integrator;
  T filter;

  [[nodiscard]] constexpr T output(T error, const PidGains<T>& gains) const {
    return saturate(add(add(multiply(gains.p, error), integrator), derivative(error, gains)), gains.lower, gains.upper);
  }
  [[nodiscard]] constexpr T output(T error, const PidGains<T>& gains, bool reset) const {
    return reset ? DiscretePid{T{0}, T{0}}.output(error, gains) : output(error, gains);
  }

  constexpr void update(T error, const PidGains<T>& gains, T period_s) {
    const T filter_input = derivative(error, gains);  // before filter changes: the same value output() used
    filter = add(filter, multiply(period_s, filter_input));
    integrator = add(integrator, multiply(period_s, multiply(gains.i, error)));
  }

  constexpr void update_clamped(T error, const PidGains<T>& gains, T period_s) {
    const T filter_input = derivative(error, gains);
    const T unlimited = add(add(multiply(gains.p, error), integrator), filter_input);
    const T increment = multiply(period_s, multiply(gains.i, error));
    const bool clamped = (unlimited > gains.upper && increment > T{0}) || (unlimited < gains.lower && increment < T{0});
    filter = add(filter, multiply(period_s, filter_input));
    if (!clamped) integrator = add(integrator, increment);
  }

  constexpr void update(T error, const PidGains<T>& gains, T period_s, bool reset) {
    if (reset) {
      *this = {T{0}, T{0}};
    } else {
      update(error, gains, period_s);
    }
  }
  constexpr void update_clamped(T error, const PidGains<T>& gains, T period_s, bool reset) {
    if (reset) {
      *this = {T{0}, T{0}};
    } else {
      update_clamped(error, gains, period_s);
    }
  }

 private:
  [[nodiscard]] constexpr T derivative(T error, const PidGains<T>& gains) const {
    return multiply(gains.n, subtract(multiply(gains.d, error), filter));
  }
};

// Counts 0, 1, ..., limit, 0, 1, ... (Simulink's Counter Limited): y(k) = c(k);
//   c(k+1) = c(k) >= limit ? 0 : add(c(k), 1)
// A count above the limit (after the limit was lowered) restarts at 0 too.
template <Number T>
struct Counter {
  T count;

  [[nodiscard]] constexpr T output() const { return count; }
  constexpr void update(T limit) { count = count >= limit ? T{0} : add(count, T{1}); }
};

enum class Edge : std::uint8_t { rising, falling, either };

// Detects edges of u from one call to the next (Simulink's Detect Rise Positive and Detect Fall Nonpositive):
//   rising   previous <= 0 and u > 0   (bool: false, then true)
//   falling  previous > 0 and u <= 0   (bool: true, then false)
//   either   rising or falling
// and then remembers u. A NaN is neither <= 0 nor > 0, so no edge leads to or from it. previous starts as the value
// before the first step; 0 (false) means a first input above 0 (true) is a rising edge.
template <Element T>
struct EdgeDetector {
  T previous;

  constexpr bool detect(Edge edge, T u) {
    const T before = previous;
    previous = u;
    // The input first: while it stays on one side, the compiler need not look at what it was before.
    const bool rising = is_high(u) && is_low(before);
    const bool falling = is_low(u) && is_high(before);
    switch (edge) {
      case Edge::rising: return rising;
      case Edge::falling: return falling;
      case Edge::either: return rising || falling;
    }
    return false;  // not an enumerator: unreachable for a valid Edge
  }

 private:
  static constexpr bool is_high(T value) {
    if constexpr (std::is_same_v<T, bool>) {
      return value;
    } else {
      return value > T{0};
    }
  }
  static constexpr bool is_low(T value) {
    if constexpr (std::is_same_v<T, bool>) {
      return !value;
    } else {
      return value <= T{0};
    }
  }
};

}  // namespace duet::blocks
