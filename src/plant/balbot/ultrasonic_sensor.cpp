#include "ultrasonic_sensor.hpp"

#include <cmath>
#include <cstdint>

namespace duet::plant::balbot {
namespace {

constexpr Nanoseconds shortest_trigger = 10'000;
constexpr Nanoseconds out_of_range_echo = 38'000'000;
constexpr double nearest_m = 0.02;
constexpr double farthest_m = 4.0;

}  // namespace

UltrasonicSensor::UltrasonicSensor(const BalbotParameters& p)
    : delay_(std::llround(p.ultrasonic_echo_delay_s * 1e9)), speed_of_sound_(p.speed_of_sound_m_s) {}

void UltrasonicSensor::trigger(Nanoseconds now, bool high) {
  if (high && !trigger_high_) trigger_rise_ = now;
  if (!high && trigger_high_ && now - trigger_rise_ >= shortest_trigger && !measuring_) {
    measuring_ = true;
    echo_rise_ = now + delay_;
  }
  trigger_high_ = high;
}

Nanoseconds UltrasonicSensor::next_echo_edge() const {
  if (!measuring_) return INT64_MAX;
  return echo_high_ ? echo_fall_ : echo_rise_;
}

bool UltrasonicSensor::echo_edge(Nanoseconds now, double distance_m) {
  if (!echo_high_) {
    echo_high_ = true;
    const bool in_range = distance_m >= nearest_m && distance_m <= farthest_m;
    echo_fall_ = now + (in_range ? std::llround(2 * distance_m / speed_of_sound_ * 1e9) : out_of_range_echo);
  } else {
    echo_high_ = false;
    measuring_ = false;
  }
  return echo_high_;
}

}  // namespace duet::plant::balbot
