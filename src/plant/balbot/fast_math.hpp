#pragma once
// sin and cos together, cheaper than the C library's and the same on every machine: the angle reduced to
// [-pi/4, pi/4] by multiples of pi/2 (in two parts, exact for the angles a robot turns through), then the Taylor
// series to the 16th/17th power, whose remainder there is below 1e-16.

#include <array>
#include <cmath>
#include <cstddef>

namespace duet::plant::balbot {

struct SineCosine {
  double sine = 0;
  double cosine = 1;
};

inline SineCosine sine_cosine(double x) {
  if (!(std::abs(x) < 1e6)) return {std::sin(x), std::cos(x)};         // never for a robot's angles: NaN or huge
  constexpr double two_over_pi = 0.63661977236758134308;               // only picks the quadrant
  constexpr double pi_over_2_high = 1.570796326734125614166259765625;  // 13493037704 / 2^33: k * high is exact
  constexpr double pi_over_2_low = 6.077100506506192601e-11;           // pi/2 - high
  const double scaled = x * two_over_pi;
  const auto quarter_turns = static_cast<long long>(scaled + (scaled >= 0 ? 0.5 : -0.5));
  const auto k = static_cast<double>(quarter_turns);
  const double r = (x - k * pi_over_2_high) - k * pi_over_2_low;
  const double r2 = r * r;
  // sin r = r (1 - r2/3! + r2^2/5! - ...), cos r = 1 - r2/2! + r2^2/4! - ..., by Horner's rule.
  constexpr std::array<double, 9> sine_terms{1.0,
                                             -1.0 / 6,
                                             1.0 / 120,
                                             -1.0 / 5040,
                                             1.0 / 362880,
                                             -1.0 / 39916800,
                                             1.0 / 6227020800,
                                             -1.0 / 1307674368000,
                                             1.0 / 355687428096000};
  constexpr std::array<double, 9> cosine_terms{1.0,
                                               -1.0 / 2,
                                               1.0 / 24,
                                               -1.0 / 720,
                                               1.0 / 40320,
                                               -1.0 / 3628800,
                                               1.0 / 479001600,
                                               -1.0 / 87178291200,
                                               1.0 / 20922789888000};
  double s = sine_terms.back();
  double c = cosine_terms.back();
  for (std::size_t i = sine_terms.size() - 1; i-- > 0;) {
    s = s * r2 + sine_terms[i];
    c = c * r2 + cosine_terms[i];
  }
  s *= r;
  const auto quadrant = quarter_turns & 3;
  switch (quadrant) {
    case 0: return {s, c};
    case 1: return {c, -s};
    case 2: return {-s, -c};
    default: return {-c, s};
  }
}

}  // namespace duet::plant::balbot
