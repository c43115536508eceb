#include "mpu6500.hpp"

#include <algorithm>
#include <cmath>

namespace duet::plant::balbot {
namespace {

// Register addresses (MPU-6500 register map).
constexpr int smplrt_div = 0x19;
constexpr int config = 0x1A;
constexpr int gyro_config = 0x1B;
constexpr int accel_config = 0x1C;
constexpr int int_pin_cfg = 0x37;
constexpr int int_enable = 0x38;
constexpr int int_status = 0x3A;
constexpr int accel_xout_h = 0x3B;
constexpr int gyro_zout_l = 0x48;
constexpr int signal_path_reset = 0x68;
constexpr int user_ctrl = 0x6A;
constexpr int pwr_mgmt_1 = 0x6B;
constexpr int who_am_i = 0x75;

constexpr std::uint8_t latch_int_en = 0x20;  // INT_PIN_CFG: INT stays high until cleared
constexpr std::uint8_t int_anyrd_2clear = 0x10;
constexpr std::uint8_t raw_rdy = 0x01;  // INT_ENABLE, INT_STATUS

Nanoseconds seconds(double s) { return std::llround(s * 1e9); }

// A byte the model sent: a number 0..255 (anything else counts as 0).
int byte_of(double value) { return value >= 0 && value <= 255 ? static_cast<int>(value) : 0; }

bool read_only(int address) {
  return address == int_status || (address >= accel_xout_h && address <= 0x60) || address == who_am_i;
}

// To the nearest count (halves away from zero), saturated to 16 bits.
std::int16_t saturate(double counts) {
  const double limited = std::clamp(counts, -32768.0, 32767.0);
  return static_cast<std::int16_t>(static_cast<int>(limited + (limited >= 0 ? 0.5 : -0.5)));
}

}  // namespace

Mpu6500::Mpu6500(const BalbotParameters& p, FastNormal* noise)
    : int_pulse_(seconds(p.mpu_int_pulse_s)),
      reset_hold_(seconds(p.mpu_reset_hold_s)),
      clock_phase_(seconds(p.mpu_clock_phase_s)),
      accel_noise_g_(p.accel_noise_g),
      gyro_noise_deg_s_(p.gyro_noise_deg_s),
      noise_(noise) {
  // Power-on: the reset values, answering at once (the start-up time is not modelled).
  reset(0);
  deaf_until_ = 0;
  clock_anchor_ = clock_phase_;
}

void Mpu6500::reset(Nanoseconds now) {
  registers_.fill(0);
  registers_[pwr_mgmt_1] = 0x01;  // awake, clock auto-selected
  registers_[who_am_i] = 0x70;
  deaf_until_ = now + reset_hold_;
  clock_anchor_ = deaf_until_ + clock_phase_;
  int_high_until_ = INT64_MIN;
  next_data_ready_ = never;
  accel_lsb_per_g_ = 16384;
  gyro_lsb_per_deg_s_ = 131;
}

bool Mpu6500::awake(Nanoseconds now) const {
  const std::uint8_t power = registers_[pwr_mgmt_1];
  return now >= deaf_until_ && (power & 0x40U) == 0 && (power & 0x07U) != 7;
}

Nanoseconds Mpu6500::sample_period() const {
  // Internal rate 1 kHz with the low-pass filter on (DLPF_CFG 1..6), 8 kHz otherwise (FCHOICE_B taken as 0).
  const int dlpf = registers_[config] & 0x07;
  const Nanoseconds internal = dlpf >= 1 && dlpf <= 6 ? 1'000'000 : 125'000;
  return internal * (1 + registers_[smplrt_div]);
}

void Mpu6500::reschedule(Nanoseconds now) {
  if (!awake(now) || (registers_[int_enable] & raw_rdy) == 0) {
    next_data_ready_ = never;
    return;
  }
  const Nanoseconds period = sample_period();
  Nanoseconds next = clock_anchor_ + std::max<Nanoseconds>(0, (now - clock_anchor_ + period - 1) / period) * period;
  if (next <= last_data_ready_) next += period;
  next_data_ready_ = next;
}

bool Mpu6500::needs_sample_for(Nanoseconds now, std::span<const double> mosi) const {
  if (mosi.size() < 2 || now < deaf_until_ || next_data_ready_ != never) return false;
  const int first = byte_of(mosi[0]);
  if ((first & 0x80) == 0) return false;
  const int start = first & 0x7F;
  const int end = start + static_cast<int>(mosi.size()) - 2;
  return start <= gyro_zout_l && end >= accel_xout_h;
}

void Mpu6500::store(const ImuSample& sample) {
  const double accel_lsb = accel_lsb_per_g_;
  const double gyro_lsb = gyro_lsb_per_deg_s_;
  std::array<std::int16_t, 7> words{};
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const double accel_noise = noise_ != nullptr ? accel_noise_g_ * (*noise_)() : 0.0;
    words[axis] = saturate((sample.accel_g[axis] + accel_noise) * accel_lsb);
  }
  words[3] = saturate((sample.temperature_c - 21) * 333.87);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    const double gyro_noise = noise_ != nullptr ? gyro_noise_deg_s_ * (*noise_)() : 0.0;
    words[4 + axis] = saturate((sample.gyro_deg_s[axis] + gyro_noise) * gyro_lsb);
  }
  for (std::size_t word = 0; word < words.size(); ++word) {
    const auto bits = static_cast<std::uint16_t>(words[word]);
    registers_[accel_xout_h + 2 * word] = static_cast<std::uint8_t>(bits >> 8U);
    registers_[accel_xout_h + 2 * word + 1] = static_cast<std::uint8_t>(bits & 0xFFU);
  }
}

bool Mpu6500::data_ready(Nanoseconds now, const ImuSample& sample) {
  store(sample);
  last_data_ready_ = now;
  next_data_ready_ = now + sample_period();
  registers_[int_status] |= raw_rdy;
  const bool rose = !int_pin_high(now);
  int_high_until_ = (registers_[int_pin_cfg] & latch_int_en) != 0 ? never : now + int_pulse_;
  return rose;
}

void Mpu6500::clear_status(Nanoseconds now) {
  registers_[int_status] = 0;
  if ((registers_[int_pin_cfg] & latch_int_en) != 0) int_high_until_ = std::min(int_high_until_, now);
}

std::uint8_t Mpu6500::read_register(Nanoseconds now, int address) {
  const std::uint8_t value = registers_[static_cast<std::size_t>(address)];
  if (address == int_status || (registers_[int_pin_cfg] & int_anyrd_2clear) != 0) clear_status(now);
  return value;
}

void Mpu6500::write_register(Nanoseconds now, int address, std::uint8_t value) {
  if (read_only(address)) return;
  const bool was_awake = awake(now);
  if (address == smplrt_div || address == config) {
    // A new rate takes over from the last sample instant of the old one.
    const Nanoseconds period = sample_period();
    if (now > clock_anchor_) clock_anchor_ += (now - clock_anchor_) / period * period;
  }
  if (address == user_ctrl) value &= 0xF8U;  // FIFO, I2C master and signal-path resets clear themselves
  if (address == signal_path_reset) value = 0;
  registers_[static_cast<std::size_t>(address)] = value;
  if (address == accel_config) accel_lsb_per_g_ = 16384.0 / static_cast<double>(1U << ((value >> 3U) & 3U));
  if (address == gyro_config) {
    static constexpr std::array<double, 4> gyro_scales{131.0, 65.5, 32.8, 16.4};
    gyro_lsb_per_deg_s_ = gyro_scales[(value >> 3U) & 3U];
  }
  if (address == pwr_mgmt_1 && !was_awake && awake(now)) clock_anchor_ = now + clock_phase_;  // clock restarts
  reschedule(now);
}

void Mpu6500::transfer(Nanoseconds now, std::span<const double> mosi, std::span<std::uint8_t> miso) {
  std::fill(miso.begin(), miso.end(), std::uint8_t{0});
  if (mosi.empty() || now < deaf_until_) return;  // after a reset the device does not answer
  const int first = byte_of(mosi[0]);
  int address = first & 0x7F;
  if ((first & 0x80) != 0) {
    const std::size_t count = mosi.size() - 1;
    const bool plain = address + static_cast<int>(count) <= 0x80 &&
                       (address > int_status || address + static_cast<int>(count) <= int_status) &&
                       (registers_[int_pin_cfg] & int_anyrd_2clear) == 0;
    if (plain && miso.size() > count) {  // a burst without side effects (the sensor data): a copy
      std::copy_n(registers_.begin() + address, count, miso.begin() + 1);
      return;
    }
    for (std::size_t i = 1; i < mosi.size(); ++i, address = (address + 1) & 0x7F) {
      const std::uint8_t value = read_register(now, address);
      if (i < miso.size()) miso[i] = value;
    }
    return;
  }
  for (std::size_t i = 1; i < mosi.size(); ++i, address = (address + 1) & 0x7F) {
    const auto value = static_cast<std::uint8_t>(byte_of(mosi[i]));
    if (address == pwr_mgmt_1 && (value & 0x80U) != 0) {
      reset(now);  // DEVICE_RESET: the rest of the transaction is lost
      return;
    }
    write_register(now, address, value);
  }
}

}  // namespace duet::plant::balbot
