#pragma once
// Design results as text for a model file: parameters in the model format (docs/MODELS.md), eigenvalues for comments.

#include <Eigen/Dense>

#include <string>
#include <string_view>

namespace duet::control {

// The shortest decimal text that reads back as the same double: "0.1", "-2.5e-07", "3". Minus zero prints as "0".
// Precondition: finite.
[[nodiscard]] std::string number_text(double value);

// `name: {value: [[a, b], [c, d]], type: TYPE}`: a model parameter, the matrix as a list of rows, every number exact
// (a single-precision parameter is rounded by whoever reads it).
[[nodiscard]] std::string parameter_text(std::string_view name, const Eigen::MatrixXd& value, std::string_view type);

// "0.99 +- 0.01i, 0.95, -0.2": the eigenvalues in their order, a complex-conjugate pair once, 6 significant digits.
[[nodiscard]] std::string eigenvalues_text(const Eigen::VectorXcd& values);

}  // namespace duet::control
