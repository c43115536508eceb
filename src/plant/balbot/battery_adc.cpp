#include "battery_adc.hpp"

#include <algorithm>
#include <cmath>

namespace duet::plant::balbot {

BatteryAdc::BatteryAdc(const BalbotParameters& p, FastNormal* noise)
    : conversion_time_(std::llround(p.adc_conversion_s * 1e9)),
      counts_per_volt_(65536.0 / (p.battery_divider_ratio * p.adc_reference_v)),
      noise_counts_(p.adc_noise_counts),
      noise_(noise) {}

void BatteryAdc::start(Nanoseconds now, double conversions) {
  if (running_ || !(conversions >= 1)) return;
  running_ = true;
  planned_ = static_cast<std::size_t>(std::min(conversions, static_cast<double>(most_conversions)));
  done_ = 0;
  started_ = now;
}

Nanoseconds BatteryAdc::next_conversion() const {
  if (!running_) return INT64_MAX;
  return started_ + static_cast<Nanoseconds>(done_ + 1) * conversion_time_;
}

bool BatteryAdc::convert(double battery_v) {
  const double noise = noise_ != nullptr ? noise_counts_ * (*noise_)() : 0.0;
  const double counts = std::clamp(std::round(battery_v * counts_per_volt_ + noise), 0.0, 65535.0);
  buffers_[1 - completed_buffer_][done_++] = static_cast<std::uint16_t>(counts);
  if (done_ < planned_) return false;
  completed_buffer_ = 1 - completed_buffer_;
  completed_count_ = planned_;
  running_ = false;
  return true;
}

std::span<const std::uint16_t> BatteryAdc::results() const {
  return {buffers_[completed_buffer_].data(), completed_count_};
}

}  // namespace duet::plant::balbot
