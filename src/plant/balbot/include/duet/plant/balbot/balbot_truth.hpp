#pragma once
// What really happens in the simulated robot, for tests and for CSV columns: the physics, the drive, the sensors'
// pins. BalbotTruth::names() and values() list the same quantities as numbers, in the same order.

#include <array>
#include <string_view>

namespace duet::plant {

// TB6612FNG modes (thesis table 5.8).
enum class MotorMode { standby, stop, short_brake, clockwise, counter_clockwise };
// A driver output pin: driven low, driven high, or off (high impedance).
enum class PinLevel { low, high, off };

struct MotorTruth {
  MotorMode mode = MotorMode::standby;
  PinLevel out1 = PinLevel::off;  // during the PWM's on-phase
  PinLevel out2 = PinLevel::off;
  double drive = 0;        // terminal voltage / battery voltage, signed: + clockwise; duty plus disturbance
  double voltage_v = 0;    // average terminal voltage, + clockwise (0 when the outputs are off)
  double current_a = 0;    // + clockwise
  double speed_rev_s = 0;  // motor shaft, + clockwise
};

struct BalbotTruth {
  double time_s = 0;
  double theta_deg = 0;  // tilt; positive: the body behind the axle (towards -x)
  double theta_dot_deg_s = 0;
  double x_m = 0;  // axle position, +x forward
  double v_m_s = 0;
  double wheel_rev_s = 0;  // wheels relative to the body (what the motors and encoders turn), + forward
  MotorTruth left;
  MotorTruth right;
  double battery_v = 0;         // terminal voltage
  double battery_a = 0;         // current drawn from the battery
  bool driver_standby = true;   // STBY low
  bool trigger_high = false;    // HC-SR04 TRIG
  bool echo_high = false;       // HC-SR04 ECHO
  double wall_distance_m = 0;   // from the sensor to the wall now
  bool mpu_int_high = false;    // MPU6500 INT pin
  double push_force_n = 0;      // scenario force acting now
  double duty_disturbance = 0;  // scenario disturbance acting now

  static constexpr std::size_t count = 29;
  // Column names: time_s, theta_deg, ..., left_mode, left_out1, ...; modes as numbers 0 standby, 1 stop,
  // 2 short brake, 3 clockwise, 4 counter-clockwise; pins 0 low, 1 high, 0.5 off; flags 0 or 1.
  [[nodiscard]] static const std::array<std::string_view, count>& names();
  [[nodiscard]] std::array<double, count> values() const;
};

}  // namespace duet::plant
