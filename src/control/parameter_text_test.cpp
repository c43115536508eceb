// Gains printed for a model file: exact numbers, the model's matrix layout, readable eigenvalues.
#include "duet/control/parameter_text.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

namespace duet::control {
namespace {

TEST(NumberText, ShortestTextThatReadsBackExactly) {
  EXPECT_EQ(number_text(0.1), "0.1");
  EXPECT_EQ(number_text(3), "3");
  EXPECT_EQ(number_text(-2.5e-7), "-2.5e-07");
  EXPECT_EQ(number_text(-0.0), "0");
  EXPECT_EQ(number_text(1.0 / 3), "0.3333333333333333");
  std::mt19937_64 random{42};
  std::uniform_real_distribution<double> mantissa{-1, 1};
  std::uniform_int_distribution<int> exponent{-300, 300};
  for (int i = 0; i < 10'000; ++i) {
    const double value = std::ldexp(mantissa(random), exponent(random));
    EXPECT_EQ(std::strtod(number_text(value).c_str(), nullptr), value) << number_text(value);
  }
}

TEST(ParameterText, AModelParameterWithRows) {
  const Eigen::MatrixXd gain{{-1.5, 0.25, 40}};
  EXPECT_EQ(parameter_text("K", gain, "single"), "K: {value: [[-1.5, 0.25, 40]], type: single}");
  const Eigen::MatrixXd column{{1}, {2e-3}};
  EXPECT_EQ(parameter_text("L", column, "double"), "L: {value: [[1], [0.002]], type: double}");
}

TEST(EigenvaluesText, ConjugatePairsOnce) {
  Eigen::VectorXcd values(4);
  values << std::complex<double>{0.9, 0.1}, std::complex<double>{0.9, -0.1}, 0.5, std::complex<double>{0.2, -0.3};
  EXPECT_EQ(eigenvalues_text(values), "0.9 +- 0.1i, 0.5, 0.2 - 0.3i");
  Eigen::VectorXcd precise(1);
  precise << 0.99876543;
  EXPECT_EQ(eigenvalues_text(precise), "0.998765");
}

}  // namespace
}  // namespace duet::control
