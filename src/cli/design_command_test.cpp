// `duet design` as a user types it: the robot's LQR and the thesis' Kalman filter from docs/examples, and bad specs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_for_test.hpp"

namespace duet::cli {
namespace {

std::string example(const char* file) { return std::string{DUET_SOURCE_DIR} + "/docs/examples/" + file; }

// A spec written to a temporary file, removed again at the end of the test.
class SpecFile {
 public:
  explicit SpecFile(const std::string& text)
      : path_(std::filesystem::temp_directory_path() / ("duet_design_" + std::to_string(::getpid()) + ".yaml")) {
    std::ofstream{path_} << text;
  }
  SpecFile(const SpecFile&) = delete;
  SpecFile& operator=(const SpecFile&) = delete;
  ~SpecFile() { std::filesystem::remove(path_); }
  [[nodiscard]] std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

// The numbers of the line `NAME: {value: [[a, b], [c, d]], ...}`, row by row.
std::vector<std::vector<double>> parameter_rows(const std::string& out, const std::string& name) {
  const std::string start = "\n" + name + ": {value: [[";
  const std::size_t begin = out.find(start);
  if (begin == std::string::npos) return {};
  const std::size_t first = begin + start.size();
  const std::string text = out.substr(first, out.find("]]", first) - first);  // "a, b], [c, d"
  std::vector<std::vector<double>> rows;
  for (std::size_t row_start = 0;;) {
    const std::size_t row_end = text.find("], [", row_start);
    std::istringstream row{text.substr(row_start, row_end == std::string::npos ? row_end : row_end - row_start)};
    rows.emplace_back();
    for (std::string number; std::getline(row, number, ',');) rows.back().push_back(std::stod(number));
    if (row_end == std::string::npos) return rows;
    row_start = row_end + 4;
  }
}

TEST(DesignCommand, TheRobotsLqr) {
  const Outcome outcome = run({"design", "lqr", example("balbot_lqr.yaml")});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  EXPECT_EQ(outcome.out.rfind("# duet design lqr " + example("balbot_lqr.yaml") +
                                  ": u[k] = -K x[k], sampled every 0.001 s (the model discretised "
                                  "with a zero-order hold)\n# closed-loop eigenvalues (Ad - Bd K): 0.9",
                              0),
            0U)
      << outcome.out;
  EXPECT_NE(outcome.out.find("], type: single}\n"), std::string::npos) << outcome.out;
  const auto k = parameter_rows(outcome.out, "K");
  ASSERT_EQ(k.size(), 1U) << outcome.out;
  ASSERT_EQ(k[0].size(), 4U) << outcome.out;
  EXPECT_GT(k[0][2], 0) << outcome.out;  // body behind the axle (theta > 0): drive backwards (u < 0) to get under it
}

TEST(DesignCommand, TheGainReadsAsAModelParameter) {
  const Outcome design = run({"design", "lqr", example("balbot_lqr.yaml")});
  ASSERT_EQ(design.exit_code, ExitCode::success) << design.err;
  const std::size_t k = design.out.find("\nK: ");
  ASSERT_NE(k, std::string::npos) << design.out;
  const SpecFile model{"duet_model: 1\nname: gain_check\nbase_period_us: 1000\nparameters:\n  " +
                       design.out.substr(k + 1) +
                       "blocks:\n  - {name: c, type: Constant, parameters: {value: K}, outputs: {y: k}}\n"};
  const Outcome check = run({"model", "check", model.path()});
  EXPECT_EQ(check.exit_code, ExitCode::success) << check.err;
  EXPECT_EQ(check.err, "");
}

TEST(DesignCommand, AContinuousDoubleIntegratorWithTheModel) {
  // The textbook case: a double integrator weighting position and input alike, sampled every 0.1 s.
  const SpecFile spec{
      "A: [[0, 1], [0, 0]]\nB: [[0], [1]]\ncontinuous: true\nperiod_s: 0.1\nQ: {diagonal: [1, 0]}\n"
      "R: 1\nname: K_position\ntype: double\n"};
  const Outcome outcome = run({"design", "lqr", spec.path(), "--with-model"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_NE(outcome.out.find("\nAd: {value: [[1, 0.1], [0, 1]], type: double}\n"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("\nBd: {value: [[0.005000000000000001], [0.1]], type: double}\n"), std::string::npos)
      << outcome.out;
  const auto k = parameter_rows(outcome.out, "K_position");
  ASSERT_EQ(k.size(), 1U) << outcome.out;
  ASSERT_EQ(k[0].size(), 2U) << outcome.out;
  EXPECT_GT(k[0][0], 0);
  EXPECT_GT(k[0][1], 0);
  EXPECT_NE(outcome.out.find("# closed-loop eigenvalues (Ad - Bd K_position): 0."), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("i\n"), std::string::npos) << outcome.out;  // a complex pair: a damped oscillation
}

TEST(DesignCommand, TheThesisKalmanFilter) {
  const Outcome outcome = run({"design", "kalman", example("thesis_kalman.yaml")});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_NE(outcome.out.find("x[k|k] = x[k|k-1] + L (y[k] - C x[k|k-1]), x[k+1|k] = Ad x[k|k], sampled every 0.001 s\n"
                             "# estimator eigenvalues (Ad (I - L C)): 0.99"),
            std::string::npos)
      << outcome.out;
  const auto l = parameter_rows(outcome.out, "L");
  ASSERT_EQ(l.size(), 2U) << outcome.out;
  ASSERT_EQ(l[1].size(), 2U) << outcome.out;
  EXPECT_NEAR(l[1][1], 1, 1e-3) << outcome.out;     // the gyro is trusted
  EXPECT_NEAR(l[0][1], 1e-3, 1e-5) << outcome.out;  // and integrated into the tilt over one period
  EXPECT_LT(l[0][0], 1e-3) << outcome.out;          // the accelerometer's noisy tilt only slowly
}

TEST(DesignCommand, TheRobotsPid) {
  const Outcome outcome = run({"design", "pid", example("balbot_pid.yaml")});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  EXPECT_NE(outcome.out.find("\n# slowest mode counted: time constant 0.063"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("\nN: {value: 28.234, type: single}\n"), std::string::npos) << outcome.out;
  for (const char* gain : {"\nP: {value: 0.", "\nI: {value: ", "\nD: {value: 0."}) {
    EXPECT_NE(outcome.out.find(gain), std::string::npos) << gain;
  }
}

TEST(DesignCommand, ThePidsModesForGivenGains) {
  const Outcome thesis = run({"design", "pid", example("balbot_pid.yaml"), "--gains", "0.0196", "0", "0.0187"});
  ASSERT_EQ(thesis.exit_code, ExitCode::success) << thesis.err;
  EXPECT_NE(thesis.out.find("\n# unstable: the largest mode grows e-fold every 0.412 s\n"), std::string::npos)
      << thesis.out;
  const Outcome shipped = run({"design", "pid", example("balbot_pid.yaml"), "--gains", "0.3", "8", "0.06"});
  EXPECT_NE(shipped.out.find("\n# slowest mode counted: time constant 0.269 s (the filter's mode, time constant 273 s, "
                             "left out)\n# outside the criterion's limits\n"),
            std::string::npos)
      << shipped.out;
}

TEST(DesignCommand, BadSpecsSayWhereAndWhy) {
  const SpecFile missing{"A: [[1, 1], [0, 1]]\nB: [[0], [1]]\nR: 1\n"};
  const Outcome no_q = run({"design", "lqr", missing.path()});
  EXPECT_EQ(no_q.exit_code, ExitCode::failure);
  EXPECT_EQ(no_q.out, "");
  EXPECT_EQ(no_q.err, "duet design lqr: " + missing.path() +
                          ":1:1: 'Q' is missing (2x2: a row and a column per state, like A)\n");

  const SpecFile sizes{"A: [[1, 1], [0, 1]]\nB: [[0], [1], [2]]\nQ: 1\nR: 1\n"};
  EXPECT_EQ(run({"design", "lqr", sizes.path()}).err,
            "duet design lqr: " + sizes.path() + ":2:4: B has 3 rows; A has 2 (a row per state)\n");

  const SpecFile words{"A: [[1, 1], [0, one]]\nB: [[0], [1]]\nQ: 1\nR: 1\n"};
  EXPECT_EQ(run({"design", "lqr", words.path()}).err,
            "duet design lqr: " + words.path() + ":1:17: A: row 2: expected a number, got 'one'\n");

  const SpecFile unreachable{"A: [[2, 0], [0, 0.5]]\nB: [[0], [1]]\nQ: {diagonal: [1, 1]}\nR: 1\n"};
  const Outcome stuck = run({"design", "lqr", unreachable.path()});
  EXPECT_EQ(stuck.exit_code, ExitCode::failure);
  EXPECT_EQ(stuck.err, "duet design lqr: " + unreachable.path() +
                           ":2:4: (A, B) is not stabilisable: the inputs cannot move the mode at eigenvalue 2 "
                           "(magnitude 2)\n");

  const SpecFile blind{"A: [[1.5, 0], [0, 0.5]]\nC: [[0, 1]]\nG: [[1], [1]]\nQ: 1\nR: 1\n"};
  EXPECT_EQ(run({"design", "kalman", blind.path()}).err,
            "duet design kalman: " + blind.path() +
                ":2:4: (A, C) is not detectable: the outputs do not see the mode at eigenvalue 1.5 (magnitude 1.5)\n");

  EXPECT_EQ(run({"design", "lqr", "/nonexistent.yaml"}).err, "duet design lqr: /nonexistent.yaml: cannot open\n");
  EXPECT_EQ(run({"design", "lqr"}).exit_code, ExitCode::usage);
  EXPECT_EQ(run({"design", "lq", "x.yaml"}).exit_code, ExitCode::usage);
}

}  // namespace
}  // namespace duet::cli
