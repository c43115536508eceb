#pragma once
// Cheap, repeatable Gaussian-like noise: std::mt19937_64 (its output sequence is fixed by the C++ standard, unlike
// std::normal_distribution's) and the Irwin-Hall sum of the four 16-bit uniforms in one draw, scaled to mean 0 and
// variance 1: bell-shaped, with tails that end at +-3.46 standard deviations (sensor noise does not miss the rest).

#include <cstdint>
#include <random>

namespace duet::plant::balbot {

class FastNormal {
 public:
  explicit FastNormal(std::uint64_t seed) : engine_(seed) {}

  double operator()() {
    const std::uint64_t a = engine_();
    const std::uint64_t sum = (a & 0xFFFFU) + ((a >> 16U) & 0xFFFFU) + ((a >> 32U) & 0xFFFFU) + (a >> 48U);
    // Each uniform on 0..65535 has mean 32767.5 and variance (65536^2 - 1) / 12.
    constexpr double mean = 4 * 32767.5;
    constexpr double inverse_deviation = 1.0 / 37837.22724;  // sqrt(4 (65536^2 - 1) / 12)
    return (static_cast<double>(sum) - mean) * inverse_deviation;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace duet::plant::balbot
