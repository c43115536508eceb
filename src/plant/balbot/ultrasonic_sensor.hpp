#pragma once
// The HC-SR04: a TRIG pulse of at least 10 us starts a measurement at its falling edge; after a fixed delay ECHO goes
// high for the sound's round trip to the wall, 2 d / v_sound, or for 38 ms when the wall is out of range (2 cm to
// 4 m). Triggers during a measurement are ignored.

#include "capture_timer.hpp"
#include "duet/plant/balbot/balbot_parameters.hpp"

namespace duet::plant::balbot {

class UltrasonicSensor {
 public:
  explicit UltrasonicSensor(const BalbotParameters& parameters);

  void trigger(Nanoseconds now, bool high);
  // When ECHO changes next (INT64_MAX: no measurement running).
  [[nodiscard]] Nanoseconds next_echo_edge() const;
  // At next_echo_edge(): the echo rises (its length from the wall distance now) or falls. Returns the new level.
  bool echo_edge(Nanoseconds now, double distance_m);

  [[nodiscard]] bool trigger_high() const { return trigger_high_; }
  [[nodiscard]] bool echo_high() const { return echo_high_; }

 private:
  Nanoseconds delay_;
  double speed_of_sound_;
  bool trigger_high_ = false;
  Nanoseconds trigger_rise_ = 0;
  bool measuring_ = false;
  bool echo_high_ = false;
  Nanoseconds echo_rise_ = 0;
  Nanoseconds echo_fall_ = 0;
};

}  // namespace duet::plant::balbot
