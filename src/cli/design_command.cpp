#include "design_command.hpp"

#include <CLI/CLI.hpp>

#include <memory>
#include <ostream>
#include <string>

#include "duet/control/design_spec.hpp"
#include "duet/control/discretise.hpp"
#include "duet/control/parameter_text.hpp"
#include "duet/control/riccati.hpp"

namespace duet::cli {
namespace {

struct DesignOptions {
  std::string file;
  bool with_model = false;
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
  return [options, lqr](Streams streams) {
    return run_design(*options, lqr->parsed() ? control::DesignKind::regulator : control::DesignKind::kalman_filter,
                      streams);
  };
}

}  // namespace duet::cli
