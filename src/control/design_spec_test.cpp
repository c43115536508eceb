// Reading `duet design` specifications: the matrix forms, the model's sources, and errors that point at the place.
#include "duet/control/design_spec.hpp"

#include <gtest/gtest.h>

#include "duet/control/balbot_model.hpp"

namespace duet::control {
namespace {

std::string error_of(std::string_view text, DesignKind kind = DesignKind::regulator) {
  auto spec = parse_design_spec(text, "s.yaml", kind);
  return spec ? "(no error)" : spec.error();
}

TEST(DesignSpec, MatricesAsRowsNumbersAndDiagonals) {
  auto spec = parse_design_spec(
      "A: [[0, 1], [0, 0]]\n"
      "B: [[0], [1]]\n"
      "continuous: true\n"
      "period_s: 0.001\n"
      "Q: {diagonal: [10, 1]}\n"
      "R: 0.5\n"
      "name: K_balance\n"
      "type: double\n",
      "s.yaml", DesignKind::regulator);
  ASSERT_TRUE(spec) << spec.error();
  EXPECT_EQ(spec.value().a, (Eigen::MatrixXd{{0, 1}, {0, 0}}));
  EXPECT_EQ(spec.value().b, (Eigen::MatrixXd{{0}, {1}}));
  EXPECT_EQ(spec.value().q, (Eigen::MatrixXd{{10, 0}, {0, 1}}));
  EXPECT_EQ(spec.value().r, (Eigen::MatrixXd{{0.5}}));
  EXPECT_TRUE(spec.value().continuous);
  EXPECT_EQ(spec.value().period_s, 0.001);
  EXPECT_EQ(spec.value().name, "K_balance");
  EXPECT_EQ(spec.value().type, "double");
  EXPECT_EQ(spec.value().model_place, "s.yaml:2:4");
}

TEST(DesignSpec, DiscreteNamesAndDefaults) {
  auto spec = parse_design_spec(
      "Ad: [[1, 0.001], [0, 1]]\nC: [[1, 0], [0, 1]]\nGd: [[0.001], [1]]\nQ: 9\n"
      "R: [[0.8, 0], [0, 330e-6]]\n",
      "s.yaml", DesignKind::kalman_filter);
  ASSERT_TRUE(spec) << spec.error();
  EXPECT_FALSE(spec.value().continuous);
  EXPECT_EQ(spec.value().b, (Eigen::MatrixXd{{0.001}, {1}}));
  EXPECT_EQ(spec.value().c, (Eigen::MatrixXd::Identity(2, 2)));
  EXPECT_EQ(spec.value().r(1, 1), 330e-6);
  EXPECT_EQ(spec.value().name, "L");
  EXPECT_EQ(spec.value().type, "single");
  EXPECT_EQ(spec.value().model_place, "s.yaml:2:4");
}

TEST(DesignSpec, TheRobotFromItsParameters) {
  auto spec = parse_design_spec(
      "balbot: {torque_constant: 0.01, motors: 2}\nperiod_s: 0.001\n"
      "Q: {diagonal: [1, 1, 100, 1]}\nR: 1\n",
      "s.yaml", DesignKind::regulator);
  ASSERT_TRUE(spec) << spec.error();
  auto model = linearise_balbot({.torque_constant = 0.01});
  ASSERT_TRUE(model);
  EXPECT_EQ(spec.value().a, model.value().a);
  EXPECT_EQ(spec.value().b, model.value().b);
  EXPECT_TRUE(spec.value().continuous);
  EXPECT_EQ(error_of("balbot: {torque: 1}\nperiod_s: 0.001\nQ: 1\nR: 1\n")
                .rfind("s.yaml:1:10: balbot: unknown field 'torque' (known: wheel_mass, ", 0),
            0U);
  EXPECT_EQ(error_of("balbot: {body_mass: -1}\nperiod_s: 0.001\nQ: 1\nR: 1\n"),
            "s.yaml:1:9: balbot: body_mass must be a positive number; it is -1");
  EXPECT_EQ(error_of("balbot: {}\nQ: 1\nR: 1\n"),
            "s.yaml:1:1: a continuous-time model needs 'period_s', the sample period in seconds, to discretise it");
}

TEST(DesignSpec, ErrorsSayWhereAndWhat) {
  EXPECT_EQ(
      error_of("B: [[0], [1]]\nQ: 1\nR: 1\n"),
      "s.yaml:1:1: 'A' is missing (the state matrix, n x n; 'Ad' is the same in discrete time), or give 'balbot'");
  EXPECT_EQ(error_of("A: [[1, 1], [0, 1]]\nB: [[0], [1]]\nR: 1\n"),
            "s.yaml:1:1: 'Q' is missing (2x2: a row and a column per state, like A)");
  EXPECT_EQ(error_of("A: [[1, 1], [0, x]]\nB: [[0], [1]]\nQ: 1\nR: 1\n"),
            "s.yaml:1:17: A: row 2: expected a number, got 'x'");
  EXPECT_EQ(error_of("A: [[1, 1], [0]]\nB: [[0], [1]]\nQ: 1\nR: 1\n"),
            "s.yaml:1:13: A: row 2 has 1 numbers; row 1 has 2");
  EXPECT_EQ(
      error_of("A: [1, 1]\nB: [[0], [1]]\nQ: 1\nR: 1\n").rfind("s.yaml:1:4: A: expected a matrix as a list of rows", 0),
      0U);
  EXPECT_EQ(error_of("A: [[1, 1], [0, 1]]\nB: [[0, 1]]\nQ: 1\nR: 1\n"),
            "s.yaml:2:4: B has 1 rows; A has 2 (a row per state)");
  EXPECT_EQ(error_of("A: [[1, 1], [0, 1]]\nB: [[0], [1]]\nQ: 1\nR: 1\n"),
            "s.yaml:3:4: Q must be 2x2 (a row and a column per state, like A); it is 1x1");
  EXPECT_EQ(error_of("A: [[1, 1], [0, 1]]\nB: [[0], [1]]\nQ: {diagonal: [1, 1]}\nR: -1\n"),
            "s.yaml:4:4: R must be positive definite; it has the eigenvalue -1");
  EXPECT_EQ(error_of("A: [[1, 1], [0, 1]]\nAd: [[1]]\nB: [[0], [1]]\nQ: 1\nR: 1\n"),
            "s.yaml:2:5: give 'A' or 'Ad', not both");
  EXPECT_EQ(error_of("Ad: [[1]]\nB: [[1]]\ncontinuous: true\nperiod_s: 1\nQ: 1\nR: 1\n"),
            "s.yaml:1:5: 'Ad' is discrete-time; with 'continuous: true' give 'A'");
  EXPECT_EQ(error_of("A: 1\nB: 1\nQ: 1\nR: 1\nS: 1\n"),
            "s.yaml:5:1: unknown field 'S' (known: A, B, Ad, Bd, balbot, continuous, period_s, Q, R, name, type)");
  EXPECT_EQ(error_of("A: 1\nB: 1\nQ: 1\nR: 1\nperiod_s: 0\n"),
            "s.yaml:5:11: period_s: the sample period must be more than 0 seconds");
  EXPECT_EQ(error_of("A: 1\nB: 1\nQ: 1\nR: 1\nname: 2K\n"),
            "s.yaml:5:7: name: expected a parameter name (letters, digits, _; not a digit first)");
  EXPECT_EQ(error_of("A: 1\nB: 1\nQ: 1\nR: 1\ntype: float\n"), "s.yaml:5:7: type: expected single or double");
  EXPECT_EQ(error_of("A: [[1, 1]\n"), "s.yaml:2:1: not YAML: end of sequence flow not found");
  EXPECT_EQ(error_of("- 1\n"), "s.yaml: expected a map of matrices: A, B, Q and R (docs/CLI.md)");
  EXPECT_EQ(error_of("A: [[1, 0], [0, 1]]\nG: [[1], [1]]\nC: [[1, 0, 0]]\nQ: 1\nR: 1\n", DesignKind::kalman_filter),
            "s.yaml:3:4: C has 3 columns; A has 2 (a column per state)");
  EXPECT_EQ(error_of("A: [[1, 0], [0, 1]]\nG: [[1], [1]]\nC: [[1, 0]]\nQ: 1\nR: [[1, 0], [0, 1]]\n",
                     DesignKind::kalman_filter),
            "s.yaml:5:4: R must be 1x1 (a row and a column per output, a row of C); it is 2x2");
  auto missing = parse_design_spec("", "s.yaml", DesignKind::regulator);
  ASSERT_FALSE(missing);
  EXPECT_EQ(load_design_spec("/nonexistent.yaml", DesignKind::regulator).error(), "/nonexistent.yaml: cannot open");
}

TEST(DesignSpec, ThePidsLoopAndCriterion) {
  auto spec = parse_pid_design_spec(
      "balbot: {volts_per_input: 7.4}\ninput_delay_s: 0.0005\nsensor_height_m: 0.075\nkalman_Q: 4\n"
      "kalman_R: {diagonal: [1, 0.001]}\nN: 50\nminimum_damping: 0.7\nmaximum_high_frequency_gain: 2\ntype: double\n",
      "s.yaml");
  ASSERT_TRUE(spec) << spec.error();
  const PidDesignSpec& pid = spec.value();
  EXPECT_EQ(pid.loop.robot.volts_per_input, 7.4);
  EXPECT_EQ(pid.loop.period_s, 0.001);  // the default
  EXPECT_EQ(pid.loop.input_delay_s, 0.0005);
  EXPECT_EQ(pid.loop.sensor_height_m, 0.075);
  EXPECT_EQ(pid.loop.kalman_q, 4);
  EXPECT_EQ(pid.loop.kalman_r(1, 1), 0.001);
  EXPECT_EQ(pid.criterion.n, 50);
  EXPECT_EQ(pid.criterion.minimum_damping, 0.7);
  EXPECT_EQ(pid.criterion.maximum_high_frequency_gain, 2);
  EXPECT_EQ(pid.type, "double");
  EXPECT_EQ(pid.model_place, "s.yaml:1:9");
}

TEST(DesignSpec, PidErrorsSayWhereAndWhat) {
  const auto error_of_pid = [](std::string_view text) {
    auto spec = parse_pid_design_spec(text, "s.yaml");
    return spec ? std::string{} : spec.error();
  };
  EXPECT_EQ(error_of_pid("period_s: 0.001\n"),
            "s.yaml:1:1: 'balbot' is missing (the robot's parameters, or {} for the defaults)");
  EXPECT_EQ(error_of_pid("balbot: {}\nQ: 1\n").rfind("s.yaml:2:1: unknown field 'Q' (known: balbot, period_s", 0), 0U);
  EXPECT_EQ(error_of_pid("balbot: {}\nkalman_R: 1\n"),
            "s.yaml:2:11: kalman_R must be 2x2 (the tilt's and the rate's noise); it is 1x1");
  EXPECT_EQ(error_of_pid("balbot: {}\nN: 0\n"), "s.yaml:2:4: N: the derivative filter's coefficient must be above 0");
  EXPECT_EQ(error_of_pid("balbot: {}\nN: x\n"), "s.yaml:2:4: N: expected a number, got 'x'");
  EXPECT_EQ(error_of_pid("- 1\n"),
            "s.yaml: expected a map of the robot's and the loop's parameters: balbot, period_s, ... (docs/CLI.md)");
}

}  // namespace
}  // namespace duet::control
