#include "duet/control/parameter_text.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <complex>
#include <sstream>

namespace duet::control {
namespace {

std::string six_digits(double value) {
  std::ostringstream text;
  text.precision(6);
  text << (value == 0 ? 0.0 : value);
  return text.str();
}

}  // namespace

std::string number_text(double value) {
  if (value == 0) return "0";
  std::array<char, 32> buffer{};
  // Without a format or precision, to_chars writes the shortest text that round-trips (C++17 [charconv.to.chars]).
  const auto written = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), written.ptr};
}

std::string parameter_text(std::string_view name, const Eigen::MatrixXd& value, std::string_view type) {
  std::string text{name};
  text += ": {value: [";
  for (Eigen::Index row = 0; row < value.rows(); ++row) {
    text += row == 0 ? "[" : ", [";
    for (Eigen::Index column = 0; column < value.cols(); ++column) {
      if (column > 0) text += ", ";
      text += number_text(value(row, column));
    }
    text += "]";
  }
  text += "], type: ";
  text += type;
  text += "}";
  return text;
}

std::string eigenvalues_text(const Eigen::VectorXcd& values) {
  std::string text;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    const std::complex<double> value = values(i);
    if (!text.empty()) text += ", ";
    text += six_digits(value.real());
    if (value.imag() == 0) continue;
    const bool pair = i + 1 < values.size() && values(i + 1) == std::conj(value);
    text += pair ? " +- " : value.imag() < 0 ? " - " : " + ";
    text += six_digits(std::abs(value.imag())) + "i";
    if (pair) ++i;
  }
  return text;
}

}  // namespace duet::control
