// The Discrete PID Controller's options and the signals' data types (testing/pid_options.mdl, a classic .mdl of
// R2018b written by hand, its variables in testing/pid_options.m): imported, checked as duet checks a model, simulated,
// and every output compared with what Simulink's blocks compute by their documentation, computed here step by step.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "duet/model/model_file.hpp"
#include "duet/model/simulation.hpp"
#include "duet/simulink_import/import.hpp"
#include "duet/simulink_import/simulink_file.hpp"
#include "testing/import_harness.hpp"

namespace duet::simulink_import {
namespace {

using ::testing::HasSubstr;
using Steps = std::vector<double>;

const std::filesystem::path testing = DUET_SIMULINK_TESTING_DIR;
constexpr double fixed_step_s = 0.01;  // the model's FixedStep
constexpr std::size_t step_count = 60;

// The error the PIDs see: 1 for 0.4 s, long enough for the limited ones to saturate and wind up, then -0.5.
double error_at(std::size_t step) { return step < 40 ? 1.0 : -0.5; }
// The single-typed inport x: 1.5 for 0.2 s, then -0.7 (which single does not hold exactly).
double x_at(std::size_t step) { return step < 20 ? 1.5 : -0.7; }
// The conversions' input u, a value a step, round and round.
const Steps u_values{2.7, -3.9, 300.5, -300.5, 0, 0.4};
double u_at(std::size_t step) { return u_values[step % u_values.size()]; }

// One Discrete PID Controller's dialog, in the type it computes in.
template <typename T>
struct PidDialog {
  T p = 0;
  T i = 0;
  T d = 0;
  T n = 100;
  T lower = -std::numeric_limits<T>::infinity();
  T upper = std::numeric_limits<T>::infinity();
  bool clamping = false;
};

// The Discrete PID Controller as its documentation gives it: parallel form, forward Euler integrator and filter,
//   u = P e + I Ts/(z-1) e + D N / (1 + N Ts/(z-1)) e, limited to [lower, upper].
// Step by step: the integrator's output x(k+1) = x(k) + Ts I e(k); the derivative term d(k) = N (D e(k) - f(k)) with
// the filter's state f(k+1) = f(k) + Ts d(k). Clamping holds x while the sum before the limit is beyond one and I e
// has the sign of the excess (the clamping circuit's dead zone and sign comparison). Written out here, not duet's.
template <typename T>
Steps simulink_pid(const PidDialog<T>& pid, const std::function<double(std::size_t)>& input) {
  const T ts = static_cast<T>(fixed_step_s);
  T integrator = 0;
  T filter = 0;
  Steps outputs;
  for (std::size_t k = 0; k < step_count; ++k) {
    const T e = static_cast<T>(input(k));
    const T derivative = pid.n * (pid.d * e - filter);
    const T sum = pid.p * e + integrator + derivative;
    const T limited = std::clamp(sum, pid.lower, pid.upper);
    outputs.push_back(static_cast<double>(limited));
    const T integrand = pid.i * e;
    const bool clamped = pid.clamping && (sum - limited) * integrand > 0;
    filter += ts * derivative;
    if (!clamped) integrator += ts * integrand;
  }
  return outputs;
}

void expect_near(const Steps& actual, const Steps& expected, double tolerance, const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  for (std::size_t k = 0; k < actual.size(); ++k) EXPECT_NEAR(actual[k], expected[k], tolerance) << what << " " << k;
}

struct Simulated {
  ImportResult imported;
  std::map<std::string, Steps> outports;  // every value each root outport wrote, a step after a step
  bool complete = false;                  // all 15 outports, each with a value for every step
};

Simulated import_and_simulate() {
  Simulated result;
  const auto model = read_simulink_file(testing / "pid_options.mdl");
  if (model) {
    EXPECT_EQ(model.value().format, "mdl (classic)");
  }
  result.imported = imported_with(model, "pid_options.m");
  std::unique_ptr<model::Model> keep;
  const auto build = checked(result.imported, keep);
  if (!build) return result;
  Ports plant{std::map<std::string, Ports::Inport>{{"inport:e", error_at}, {"inport:u", u_at}, {"inport:x", x_at}}};
  const double duration_s = fixed_step_s * static_cast<double>(step_count - 1);
  auto simulated = model::simulate(*build->program, plant, {.duration_s = duration_s, .record_plant = false});
  EXPECT_TRUE(simulated) << (simulated ? "" : simulated.error());
  for (const auto& [resource, values] : plant.history) {
    if (resource.starts_with("outport:")) result.outports[resource.substr(8)] = values;
  }
  result.complete = result.outports.size() == 15 &&
                    std::all_of(result.outports.begin(), result.outports.end(),
                                [](const auto& outport) { return outport.second.size() == step_count; });
  EXPECT_TRUE(result.complete) << ::testing::PrintToString(result.outports);
  return result;
}

TEST(PidOptions, ImportsEveryControllerTypeTheGainsOfVariablesTunable) {
  const Simulated simulated = import_and_simulate();
  const ImportResult& imported = simulated.imported;
  for (const char* type : {"P", "PI", "PD", "PID", "I"})
    EXPECT_EQ(verdict(imported, std::string{"pid_options/"} + type).what, std::string{"DiscretePid ("} + type + ")");
  EXPECT_EQ(verdict(imported, "pid_options/PID clamped").what, "DiscretePid (PID)");
  // The variables of pid_options.m the dialogs name are model parameters of their names, tunable over XCP.
  for (const char* tunable : {"  Kp: {value: 1, ", "  Ki: {value: 20, ", "  Kd: {value: 0.05, ", "  Nf: {value: 50, ",
                              "  limit: {value: 1.5, "})
    EXPECT_THAT(imported.model_text, HasSubstr(tunable));
  // An I controller has no proportional term, whatever its dialog's P (3) holds.
  EXPECT_THAT(imported.model_text, HasSubstr("parameters: {p: 0, i: Ki, d: 0}"));
  // "-limit" is an expression, not a variable: its value.
  EXPECT_THAT(imported.model_text, HasSubstr("lower: -1.5, upper: limit, anti_windup: clamping"));
}

TEST(PidOptions, EachControllerComputesWhatSimulinksDiscretePidDoes) {
  const Simulated simulated = import_and_simulate();
  ASSERT_TRUE(simulated.complete);
  const auto& y = simulated.outports;
  // Kp 1, Ki 20, Kd 0.05, Nf 50 (pid_options.m); the P controller's gain 2 is a literal.
  const PidDialog<double> p{.p = 2};
  const PidDialog<double> pi{.p = 1, .i = 20};
  const PidDialog<double> pd{.p = 1, .d = 0.05, .n = 50};
  const PidDialog<double> pid{.p = 1, .i = 20, .d = 0.05, .n = 50};
  PidDialog<double> limited = pid;
  limited.lower = -1.5;
  limited.upper = 1.5;
  PidDialog<double> clamped = limited;
  clamped.clamping = true;
  const PidDialog<double> i_only{.i = 20};
  constexpr double exactly = 0;  // duet rounds in the order of Simulink's block
  expect_near(y.at("y_p"), simulink_pid(p, error_at), exactly, "P");
  expect_near(y.at("y_pi"), simulink_pid(pi, error_at), exactly, "PI");
  expect_near(y.at("y_pd"), simulink_pid(pd, error_at), exactly, "PD");
  expect_near(y.at("y_pid"), simulink_pid(pid, error_at), exactly, "PID");
  expect_near(y.at("y_pid_limited"), simulink_pid(limited, error_at), exactly, "PID limited");
  expect_near(y.at("y_pid_clamped"), simulink_pid(clamped, error_at), exactly, "PID clamped");
  expect_near(y.at("y_i"), simulink_pid(i_only, error_at), exactly, "I");

  constexpr double tolerance = 1e-12;  // the decimal values by hand are not the steps' binary sums
  // A few values by hand. P: 2 e. PI: e + 0.2 k for an error of 1 held k steps.
  EXPECT_EQ(y.at("y_p")[39], 2.0);
  EXPECT_EQ(y.at("y_p")[40], -1.0);
  EXPECT_NEAR(y.at("y_pi")[3], 1.6, tolerance);
  // PD at the step: P e + N D e = 1 + 2.5; the filter then decays by (1 - N Ts) = 0.5 a step: 1 + 1.25.
  EXPECT_NEAR(y.at("y_pd")[0], 3.5, tolerance);
  EXPECT_NEAR(y.at("y_pd")[1], 2.25, tolerance);
  // I: 0.2 a step from 0, so 0.2 k; at step 40 it is 8 and the error -0.5 takes 0.1 a step off.
  EXPECT_NEAR(y.at("y_i")[40], 8.0, tolerance);
  EXPECT_NEAR(y.at("y_i")[45], 7.5, tolerance);
  // Limited to 1.5. Without anti-windup the integrator winds up to 8 by step 40 and, 0.1 a step off after the error
  // turned, keeps the output at the limit to the end. Clamping held it at 0 in steps 0 to 2 (1 + 2.5, + 1.25, + 0.625
  // beyond the limit, the filtered derivative halving), let it rise in steps 3 to 5 (step 3: 1 + 0 + 0.3125) and held
  // it at 0.6 from step 6 on: after the turn the output leaves the limit within three steps.
  EXPECT_EQ(y.at("y_pid_limited")[59], 1.5);
  EXPECT_NEAR(y.at("y_pid_clamped")[3], 1.3125, tolerance);
  EXPECT_LT(std::abs(y.at("y_pid_clamped")[45]), 0.5);  // clamping changes the result
}

TEST(PidOptions, ConversionsAndTheSingleTypedChainComputeWhatSimulinkDoes) {
  const Simulated simulated = import_and_simulate();
  ASSERT_TRUE(simulated.complete);
  const auto& y = simulated.outports;
  const auto first_six = [&y](const std::string& outport) {
    return Steps(y.at(outport).begin(), y.at(outport).begin() + 6);
  };
  // u = 2.7, -3.9, 300.5, -300.5, 0, 0.4
  EXPECT_EQ(first_six("y_to_boolean"), (Steps{1, 1, 1, 1, 0, 1}));       // u ~= 0; rounding and saturation do not apply
  EXPECT_EQ(first_six("y_to_int8"), (Steps{2, -3, 127, -128, 0, 0}));    // toward zero, saturated to [-128, 127]
  EXPECT_EQ(first_six("y_to_uint8"), (Steps{2, 0, 255, 0, 0, 0}));       // toward zero, saturated to [0, 255]
  EXPECT_EQ(first_six("y_int8_to_uint8"), (Steps{2, 0, 127, 0, 0, 0}));  // int8 to uint8, saturated
  // To single: to the nearest single, whatever its RndMeth (Floor, for integer outputs only) says.
  Steps singles;
  for (const double u : u_values) singles.push_back(static_cast<double>(static_cast<float>(u)));
  EXPECT_EQ(first_six("y_to_single"), singles);
  EXPECT_NE(singles[0], 2.7);

  // The Inport x declares single: the chain after it computes in single.
  for (std::size_t k : {0U, 30U}) {
    const float x = static_cast<float>(x_at(k));
    EXPECT_EQ(y.at("y_x_to_double")[k], static_cast<double>(x)) << k;    // 1.5, then single's -0.7
    EXPECT_EQ(y.at("y_x_gain")[k], static_cast<double>(0.1F * x)) << k;  // the gain 0.1 in single
  }
  EXPECT_NE(y.at("y_x_gain")[30], -0.07);
  // PI on x in single: P 0.5, I 10, limited to [-1, 1] with clamping. At x = 1.5: 0.75, 0.9, then 1.05 beyond 1 holds
  // the integrator at 0.3 until x turns; at x = -0.7: -0.35 + 0.3 = -0.05, then 0.07 a step down until -1 holds it.
  const PidDialog<float> pi_single{.p = 0.5F, .i = 10, .lower = -1, .upper = 1, .clamping = true};
  expect_near(y.at("y_pi_single"), simulink_pid(pi_single, x_at), 0, "PI single");
  EXPECT_NEAR(y.at("y_pi_single")[1], 0.9, 1e-6);
  EXPECT_EQ(y.at("y_pi_single")[10], 1.0);
  EXPECT_NEAR(y.at("y_pi_single")[20], -0.05, 1e-6);
  EXPECT_EQ(y.at("y_pi_single")[59], -1.0);
}

}  // namespace
}  // namespace duet::simulink_import
