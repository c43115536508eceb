#pragma once
// ADC1 channel 6 on the battery divider, read by one DMA one-shot sequence of n conversions (16-bit results,
// V_REF 3.3 V). Each conversion takes a fixed time and samples the battery's terminal voltage at its end.

#include <array>
#include <cstdint>
#include <span>

#include "capture_timer.hpp"
#include "duet/plant/balbot/balbot_parameters.hpp"
#include "fast_normal.hpp"

namespace duet::plant::balbot {

class BatteryAdc {
 public:
  static constexpr std::size_t most_conversions = 1024;

  // `noise` may be null: no noise.
  BatteryAdc(const BalbotParameters& parameters, FastNormal* noise);

  // Starts a sequence of `conversions` (1..most_conversions; ignored while one runs or when less than 1).
  void start(Nanoseconds now, double conversions);
  [[nodiscard]] Nanoseconds next_conversion() const;
  // When the last conversion of the running sequence ends (INT64_MAX: none running).
  [[nodiscard]] Nanoseconds completion() const {
    return running_ ? started_ + static_cast<Nanoseconds>(planned_) * conversion_time_ : INT64_MAX;
  }
  // At next_conversion(): converts the battery voltage; true when that completed the sequence (DMA complete).
  bool convert(double battery_v);
  // The results of the last completed sequence.
  [[nodiscard]] std::span<const std::uint16_t> results() const;

 private:
  Nanoseconds conversion_time_;
  double counts_per_volt_;
  double noise_counts_;
  FastNormal* noise_;
  std::array<std::array<std::uint16_t, most_conversions>, 2> buffers_{};
  std::size_t completed_buffer_ = 0;
  std::size_t completed_count_ = 0;
  bool running_ = false;
  std::size_t planned_ = 0;
  std::size_t done_ = 0;
  Nanoseconds started_ = 0;
};

}  // namespace duet::plant::balbot
