#pragma once
// The specification files of `duet design lqr` and `duet design kalman` (YAML, docs/CLI.md): the model's matrices as
// lists of rows, the weights, and how to print the gain. Errors name the file, line and column, and the problem.

#include <Eigen/Dense>

#include <optional>
#include <string>
#include <string_view>

#include "duet/control/pid_design.hpp"
#include "duet/support/result.hpp"

namespace duet::control {

enum class DesignKind { regulator, kalman_filter };

// A specification whose matrices have consistent sizes and whose weights are symmetric and (semi-)definite.
struct DesignSpec {
  DesignKind kind = DesignKind::regulator;
  Eigen::MatrixXd a;               // n x n
  Eigen::MatrixXd b;               // regulator: B, n x m (inputs); filter: G, n x w (noise inputs)
  Eigen::MatrixXd c;               // filter: C, p x n (outputs); empty for a regulator
  Eigen::MatrixXd q;               // regulator: state weight, n x n; filter: process noise covariance, w x w
  Eigen::MatrixXd r;               // regulator: input weight, m x m; filter: measurement noise covariance, p x p
  bool continuous = false;         // a and b are continuous-time: discretise them (zero-order hold) with period_s
  std::optional<double> period_s;  // required when continuous
  std::string name;                // the printed parameter's name: K (regulator) or L (filter) unless given
  std::string type = "single";     // the printed parameter's type: single or double
  std::string model_place;         // "file:line:column" of B (or balbot) or C: where a design failure is reported
};

// The specification of `duet design pid` (docs/CLI.md): the robot, the loop around the PID and the criterion.
struct PidDesignSpec {
  PidLoopSpec loop;
  PidCriterion criterion;
  std::string type = "single";  // the printed parameters' type: single or double
  std::string model_place;      // "file:line:column" of balbot: where a design failure is reported
};

// `text` is the file's content; `file` names it in errors.
[[nodiscard]] Result<DesignSpec> parse_design_spec(std::string_view text, const std::string& file, DesignKind kind);
[[nodiscard]] Result<DesignSpec> load_design_spec(const std::string& path, DesignKind kind);
[[nodiscard]] Result<PidDesignSpec> parse_pid_design_spec(std::string_view text, const std::string& file);
[[nodiscard]] Result<PidDesignSpec> load_pid_design_spec(const std::string& path);

}  // namespace duet::control
