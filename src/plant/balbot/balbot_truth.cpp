#include "duet/plant/balbot/balbot_truth.hpp"

namespace duet::plant {
namespace {

double number(MotorMode mode) { return static_cast<double>(static_cast<int>(mode)); }

double number(PinLevel level) {
  switch (level) {
    case PinLevel::low: return 0;
    case PinLevel::high: return 1;
    case PinLevel::off: return 0.5;
  }
  return 0.5;
}

double number(bool flag) { return flag ? 1 : 0; }

}  // namespace

const std::array<std::string_view, BalbotTruth::count>& BalbotTruth::names() {
  static constexpr std::array<std::string_view, count> list{
      "time_s",           "theta_deg",         "theta_dot_deg_s", "x_m",          "v_m_s",           "wheel_rev_s",
      "left_mode",        "left_out1",         "left_out2",       "left_drive",   "left_voltage_v",  "left_current_a",
      "left_speed_rev_s", "right_mode",        "right_out1",      "right_out2",   "right_drive",     "right_voltage_v",
      "right_current_a",  "right_speed_rev_s", "battery_v",       "battery_a",    "driver_standby",  "trigger_high",
      "echo_high",        "wall_distance_m",   "mpu_int_high",    "push_force_n", "duty_disturbance"};
  return list;
}

std::array<double, BalbotTruth::count> BalbotTruth::values() const {
  return {time_s,
          theta_deg,
          theta_dot_deg_s,
          x_m,
          v_m_s,
          wheel_rev_s,
          number(left.mode),
          number(left.out1),
          number(left.out2),
          left.drive,
          left.voltage_v,
          left.current_a,
          left.speed_rev_s,
          number(right.mode),
          number(right.out1),
          number(right.out2),
          right.drive,
          right.voltage_v,
          right.current_a,
          right.speed_rev_s,
          battery_v,
          battery_a,
          number(driver_standby),
          number(trigger_high),
          number(echo_high),
          wall_distance_m,
          number(mpu_int_high),
          push_force_n,
          duty_disturbance};
}

}  // namespace duet::plant
