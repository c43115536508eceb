#include "design_command.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "duet/control/design_spec.hpp"
#include "duet/control/discretise.hpp"
#include "duet/control/parameter_text.hpp"
#include "duet/control/pid_design.hpp"
#include "duet/control/riccati.hpp"

namespace duet::cli {
namespace {

struct DesignOptions {
  std::string file;
  bool with_model = false;
  std::vector<double> gains;  // duet design pid --gains P I D: evaluate these instead of designing
};

// The spec's model in discrete time: as given, or held over the period.
Result<control::DiscreteModel> discrete_model(const control::DesignSpec& spec) {
  if (!spec.continuous) return control::DiscreteModel{spec.a, spec.b};
  auto model = control::c2d(spec.a, spec.b, *spec.period_s);
  if (!model) return Failure{spec.model_place + ": " + model.error()};
  return model;
}

std::string sampling_text(const control::DesignSpec& spec) {
  if (!spec.period_s) return "";
  return std::string{", sampled every "} + control::number_text(*spec.period_s) + " s" +
         (spec.continuous ? " (the model discretised with a zero-order hold)" : "");
}

ExitCode run_design(const DesignOptions& options, control::DesignKind kind, Streams streams) {
  const bool regulator = kind == control::DesignKind::regulator;
  const std::string command = regulator ? "lqr" : "kalman";
  auto loaded = control::load_design_spec(options.file, kind);
  if (!loaded) {
    streams.err << "duet design " << command << ": " << loaded.error() << '\n';
    return ExitCode::failure;
  }
  const control::DesignSpec& spec = loaded.value();
  auto model = discrete_model(spec);
  if (!model) {
    streams.err << "duet design " << command << ": " << model.error() << '\n';
    return ExitCode::failure;
  }
  const control::DiscreteModel& discrete = model.value();
  const std::string& name = spec.name;
  std::string law;
  Eigen::MatrixXd gain;
  Eigen::VectorXcd eigenvalues;
  if (regulator) {
    auto design = control::dlqr(discrete.ad, discrete.bd, spec.q, spec.r);
    if (!design) {
      streams.err << "duet design lqr: " << spec.model_place << ": " << design.error() << '\n';
      return ExitCode::failure;
    }
    law = "u[k] = -" + name + " x[k]";
    gain = design.value().gain;
    eigenvalues = design.value().closed_loop_eigenvalues;
  } else {
    auto design = control::kalman_gain(discrete.ad, spec.c, discrete.bd, spec.q, spec.r);
    if (!design) {
      streams.err << "duet design kalman: " << spec.model_place << ": " << design.error() << '\n';
      return ExitCode::failure;
    }
    law = "x[k|k] = x[k|k-1] + " + name + " (y[k] - C x[k|k-1]), x[k+1|k] = Ad x[k|k]";
    gain = design.value().gain;
    eigenvalues = design.value().estimator_eigenvalues;
  }
  streams.out << "# duet design " << command << ' ' << options.file << ": " << law << sampling_text(spec) << '\n'
              << (regulator ? "# closed-loop eigenvalues (Ad - Bd " + name + "): "
                            : "# estimator eigenvalues (Ad (I - " + name + " C)): ")
              << control::eigenvalues_text(eigenvalues) << '\n'
              << control::parameter_text(name, gain, spec.type) << '\n';
  if (options.with_model) {
    streams.out << control::parameter_text("Ad", discrete.ad, spec.type) << '\n'
                << control::parameter_text(regulator ? "Bd" : "Gd", discrete.bd, spec.type) << '\n';
  }
  return ExitCode::success;
}

// A time constant in seconds to 3 significant digits.
std::string seconds_text(double seconds) {
  std::ostringstream text;
  text.precision(3);
  text << seconds << " s";
  return text.str();
}

std::string modes_text(const control::PidEvaluation& evaluation, double period_s) {
  std::string text = "# closed-loop eigenvalues without the rolling mode at 1: " +
                     control::eigenvalues_text(evaluation.moving_eigenvalues) + "\n";
  if (std::abs(evaluation.moving_eigenvalues(0)) >= 1) {
    const double growth = std::log(std::abs(evaluation.moving_eigenvalues(0))) / period_s;
    return text + "# unstable: the largest mode grows e-fold every " + seconds_text(1 / growth) + "\n";
  }
  text += "# slowest mode counted: time constant " + seconds_text(evaluation.slowest_time_constant_s);
  if (evaluation.filter_mode) {
    text += " (the filter's mode, time constant " +
            seconds_text(-period_s / std::log(std::abs(*evaluation.filter_mode))) + ", left out)";
  }
  return text + "\n";
}

ExitCode run_pid_design(const DesignOptions& options, Streams streams) {
  auto loaded = control::load_pid_design_spec(options.file);
  if (!loaded) {
    streams.err << "duet design pid: " << loaded.error() << '\n';
    return ExitCode::failure;
  }
  const control::PidDesignSpec& spec = loaded.value();
  auto loop = control::PidLoop::make(spec.loop);
  if (!loop) {
    streams.err << "duet design pid: " << spec.model_place << ": " << loop.error() << '\n';
    return ExitCode::failure;
  }
  streams.out << "# duet design pid " << options.file
              << ": y = P e + I Ts/(z-1) e + D N/(1 + N Ts/(z-1)) e, e = target - filtered tilt (deg), sampled every "
              << control::number_text(spec.loop.period_s) << " s\n";
  if (!options.gains.empty()) {
    const control::PidLoopGains gains{options.gains[0], options.gains[1], options.gains[2], spec.criterion.n};
    const control::PidEvaluation evaluation = control::evaluate_pid(loop.value(), spec.criterion, gains);
    streams.out << modes_text(evaluation, spec.loop.period_s) << "# "
                << (evaluation.within_limits ? "within the criterion's limits" : "outside the criterion's limits")
                << '\n';
    return ExitCode::success;
  }
  auto design = control::design_pid(loop.value(), spec.criterion);
  if (!design) {
    streams.err << "duet design pid: " << spec.model_place << ": " << design.error() << '\n';
    return ExitCode::failure;
  }
  const control::PidLoopGains& gains = design.value().gains;
  streams.out << modes_text(design.value().evaluation, spec.loop.period_s);
  for (const auto& [name, value] :
       {std::pair{"P", gains.p}, std::pair{"I", gains.i}, std::pair{"D", gains.d}, std::pair{"N", gains.n}}) {
    streams.out << name << ": {value: " << control::number_text(value) << ", type: " << spec.type << "}\n";
  }
  return ExitCode::success;
}

}  // namespace

Action define_design_command(CLI::App& command) {
  auto options = std::make_shared<DesignOptions>();
  command.require_subcommand(1);
  CLI::App* lqr = command.add_subcommand("lqr", "A discrete-time LQR gain K (u = -K x) from A, B, Q and R");
  CLI::App* kalman =
      command.add_subcommand("kalman", "A steady-state Kalman gain (current-estimate form) from A, C, G, Q and R");
  for (CLI::App* kind : {lqr, kalman}) {
    kind->add_option("spec", options->file, "The specification (YAML, docs/CLI.md)")->required();
    kind->add_flag("--with-model", options->with_model,
                   "Also print the discrete-time model (Ad and Bd, or Ad and Gd) as parameters");
  }
  CLI::App* pid = command.add_subcommand(
      "pid", "P, I and D for the robot's tilt PID, by the slowest closed-loop mode they can move");
  pid->add_option("spec", options->file, "The specification (YAML, docs/CLI.md)")->required();
  pid->add_option("--gains", options->gains, "Evaluate these gains instead: P I D")->expected(3);
  return [options, lqr, pid](Streams streams) {
    if (pid->parsed()) return run_pid_design(*options, streams);
    return run_design(*options, lqr->parsed() ? control::DesignKind::regulator : control::DesignKind::kalman_filter,
                      streams);
  };
}

}  // namespace duet::cli
