#include "ticks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace duet::plot {
namespace {

constexpr double largest = std::numeric_limits<double>::max();

// A span this small next to the values' size is rounding noise, not a range one can put ticks on.
bool nearly_constant(double min, double max) {
  const double size = std::max(std::abs(min), std::abs(max));
  return !(max / 2 - min / 2 > size * 1e-9 / 2);
}

Range widened(double value) {
  if (value == 0) return {-1, 1};
  const double margin = std::abs(value) / 10;
  return {std::max(value - margin, -largest), std::min(value + margin, largest)};
}

// Halves keep the span finite even from -max to +max.
double half_span(Range range) { return range.high / 2 - range.low / 2; }

}  // namespace

Range padded_range(double min, double max) {
  if (nearly_constant(min, max)) return widened(min / 2 + max / 2);
  const double margin = half_span({min, max}) / 10;
  return {std::max(min - margin, -largest), std::min(max + margin, largest)};
}

Range usable_range(double min, double max) {
  if (nearly_constant(min, max)) return widened(min / 2 + max / 2);
  return {min, max};
}

std::string decimal_label(long long multiple, int exponent) {
  const bool negative = multiple < 0;
  // The magnitude as digits; unsigned so that the smallest long long has one too.
  const unsigned long long magnitude =
      negative ? 0ULL - static_cast<unsigned long long>(multiple) : static_cast<unsigned long long>(multiple);
  std::string digits = std::to_string(magnitude);
  std::string text = negative ? "-" : "";
  if (exponent >= 0 && exponent <= 5) {
    if (magnitude == 0) return "0";
    return text + digits + std::string(static_cast<std::size_t>(exponent), '0');
  }
  if (exponent < 0 && exponent >= -4) {
    const auto decimals = static_cast<std::size_t>(-exponent);
    if (digits.size() <= decimals) digits.insert(0, decimals + 1 - digits.size(), '0');
    return text + digits.substr(0, digits.size() - decimals) + "." + digits.substr(digits.size() - decimals);
  }
  if (magnitude == 0) return "0";
  const int scientific_exponent = exponent + static_cast<int>(digits.size()) - 1;
  std::string fraction = digits.substr(1);
  while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
  return text + digits.substr(0, 1) + (fraction.empty() ? "" : "." + fraction) + "e" +
         std::to_string(scientific_exponent);
}

Ticks choose_ticks(Range range, std::size_t most) {
  constexpr std::array<int, 3> mantissas{1, 2, 5};
  constexpr double slack = 1e-9;  // 0.3 / 0.1 is 2.9999999999999996; a tick on the edge still counts
  const double rough = half_span(range) / static_cast<double>(most) * 2;
  if (!(rough > 0) || !std::isfinite(rough)) return {.step = 1, .ticks = {}};
  int exponent = static_cast<int>(std::floor(std::log10(rough))) - 1;  // from about -325 to 308
  // Steps grow by at least 2 each try, so a dozen tries go far past `rough`; the bound only guards odd input.
  for (int attempt = 0; attempt < 24; ++attempt) {
    const int mantissa = mantissas[static_cast<std::size_t>(attempt % 3)];
    if (attempt > 0 && mantissa == 1) ++exponent;
    const double step = mantissa * std::pow(10.0, exponent);
    if (!(step > 0) || !std::isfinite(step)) continue;
    const double first = std::ceil(range.low / step - slack);
    const double last = std::floor(range.high / step + slack);
    if (std::abs(first) > 1e15 || std::abs(last) > 1e15) continue;  // beyond exact integers in a double
    if (last - first + 1 > static_cast<double>(most)) continue;
    Ticks result{.step = step, .ticks = {}};
    for (auto index = static_cast<long long>(first); index <= static_cast<long long>(last); ++index) {
      result.ticks.push_back(
          {.value = static_cast<double>(index) * step, .label = decimal_label(index * mantissa, exponent)});
    }
    return result;
  }
  return {.step = range.high - range.low, .ticks = {}};
}

}  // namespace duet::plot
