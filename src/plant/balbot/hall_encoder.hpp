#pragma once
// One motor's hall encoder: signals A and B in quadrature, `edges_per_turn` rising edges of A per wheel turn relative
// to the body. The phase (in cycles of A) grows when the motor turns clockwise; A is high in the first half of each
// cycle and B from a quarter to three quarters, so at A's rising edge B is low turning clockwise (phase rising
// through a whole number) and high turning counter-clockwise (phase falling through a half).
//
// For each integration segment the encoder plans every half-cycle boundary the phase crosses on the segment's motion
// curve (splitting it where the wheels turn back, so a reversal inside a step loses nothing). Only A's rising edges
// become events (captures); the other crossings are applied as time passes them. Boundaries have a hysteresis of
// 1e-4 cycles, like a real hall sensor's (if smaller), so that rounding never counts an edge twice.

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "capture_timer.hpp"
#include "segment.hpp"

namespace duet::plant::balbot {

struct HallCrossing {
  double tau = 0;        // where in the segment
  Nanoseconds time = 0;  // when
  bool upward = false;   // the phase rises (clockwise)
  bool rising = false;   // into a high half of A: a capture
};

// Where a segment's motion turns (the roots of the wheel angle's slope in (0, 1)), with 0 and 1 around them, and
// the wheel angle at each.
struct TurningPoints {
  std::array<double, 4> bounds{};
  std::array<double, 4> angles{};
  std::size_t count = 0;
};
[[nodiscard]] TurningPoints turning_points(const Cubic& wheel_angle);

class HallEncoder {
 public:
  static constexpr std::size_t most_planned = 32;  // per segment; more are planned when these are used up

  // `direction` +1: clockwise turns the wheels forward (left motor); -1: mirrored (right motor).
  HallEncoder(double direction, int edges_per_turn, double phase_offset_cycles);

  void start(double wheel_angle);
  // Plans the crossings of the segment [start, start + length] from `from` (in tau) on.
  void plan(const Cubic& wheel_angle, const TurningPoints& turns, Nanoseconds start, Nanoseconds length, double from);
  // The next event: a rising edge, or the last planned crossing when the plan is full (then plan again from it).
  [[nodiscard]] std::optional<HallCrossing> next_event() const;
  [[nodiscard]] Nanoseconds next_event_time() const { return event_ < planned_ ? plan_[event_].time : INT64_MAX; }
  struct Taken {
    bool rising_edge = false;
    bool plan_again = false;  // the plan is used up: plan again from tau
    double tau = 0;
  };
  // Applies the crossings up to and including next_event().
  Taken take_next();
  // Applies the planned crossings before `time` and drops the rest (the segment is about to change).
  void apply_before(Nanoseconds time);

  [[nodiscard]] bool a_high() const { return (half_cycle_ & 1) == 0; }
  [[nodiscard]] bool b_high(double wheel_angle) const;
  [[nodiscard]] std::span<const HallCrossing> planned() const { return {plan_.data(), planned_}; }

 private:
  double cycles_per_radian_;
  double offset_;
  std::int64_t half_cycle_ = 0;  // floor(2 phase) with hysteresis, as of the crossings applied
  std::array<HallCrossing, most_planned> plan_{};
  std::size_t planned_ = 0;
  std::size_t applied_ = 0;  // plan_[applied_ ..] are still ahead
  std::size_t event_ = 0;    // index of next_event() in plan_ (planned_ if none)
};

}  // namespace duet::plant::balbot
