#pragma once
// `duet design lqr|kalman SPEC.yaml`: an LQR or steady-state Kalman gain, printed as a model parameter (docs/CLI.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_design_command(CLI::App& command);

}  // namespace duet::cli
