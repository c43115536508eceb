#pragma once
// The MPU6500 on SPI5 as its register map describes it, as far as the robot uses it: reset values, WHO_AM_I, device
// reset (then 100 ms deaf), sleep and clock, SMPLRT_DIV and CONFIG (the sample rate), GYRO_CONFIG and ACCEL_CONFIG
// (the full-scale ranges), INT_PIN_CFG (latching, clear on any read), INT_ENABLE, INT_STATUS (cleared by reading it),
// and the sensor registers 0x3B..0x48. The plant supplies the physical sample (in sensor axes); this class turns it
// into the register bytes with the configured scale, noise and saturation.

#include <array>
#include <cstdint>
#include <span>

#include "capture_timer.hpp"
#include "duet/plant/balbot/balbot_parameters.hpp"
#include "fast_normal.hpp"

namespace duet::plant::balbot {

constexpr Nanoseconds never = INT64_MAX;

struct ImuSample {
  std::array<double, 3> accel_g{};     // specific force along the sensor's x, y, z, in g
  std::array<double, 3> gyro_deg_s{};  // rotation rate about x, y, z
  double temperature_c = 25;
};

class Mpu6500 {
 public:
  // `noise` may be null: no noise.
  Mpu6500(const BalbotParameters& parameters, FastNormal* noise);

  // One SPI transaction (chip select low .. high) at `now`: MOSI bytes in, MISO bytes out (same count).
  void transfer(Nanoseconds now, std::span<const double> mosi, std::span<std::uint8_t> miso);
  // Whether a transaction of these bytes would read sensor data the device is not sampling by itself (the
  // data-ready interrupt is off): then the plant stores a sample of that instant first.
  [[nodiscard]] bool needs_sample_for(Nanoseconds now, std::span<const double> mosi) const;
  void store(const ImuSample& sample);

  [[nodiscard]] Nanoseconds next_data_ready() const { return next_data_ready_; }
  // At next_data_ready(): stores the sample and raises INT; true if the pin rose (an EXTI8 edge).
  bool data_ready(Nanoseconds now, const ImuSample& sample);
  // The INT pin at `now` (its pulse's end needs no event: the level is worked out when asked for).
  [[nodiscard]] bool int_pin_high(Nanoseconds now) const { return now < int_high_until_; }
  [[nodiscard]] std::uint8_t reg(int address) const { return registers_[static_cast<std::size_t>(address & 0x7F)]; }

 private:
  [[nodiscard]] bool awake(Nanoseconds now) const;
  [[nodiscard]] Nanoseconds sample_period() const;
  void reset(Nanoseconds now);
  void write_register(Nanoseconds now, int address, std::uint8_t value);
  std::uint8_t read_register(Nanoseconds now, int address);
  void clear_status(Nanoseconds now);
  void reschedule(Nanoseconds now);

  Nanoseconds int_pulse_;
  Nanoseconds reset_hold_;
  Nanoseconds clock_phase_;
  double accel_noise_g_;
  double gyro_noise_deg_s_;
  double accel_lsb_per_g_ = 16384;  // from ACCEL_CONFIG and GYRO_CONFIG
  double gyro_lsb_per_deg_s_ = 131;
  FastNormal* noise_;
  std::array<std::uint8_t, 128> registers_{};
  Nanoseconds deaf_until_ = 0;    // after a device reset
  Nanoseconds clock_anchor_ = 0;  // samples fall at clock_anchor_ + k * sample_period()
  Nanoseconds last_data_ready_ = -1;
  Nanoseconds next_data_ready_ = never;
  Nanoseconds int_high_until_ = INT64_MIN;  // never while latched
};

}  // namespace duet::plant::balbot
