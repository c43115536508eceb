#pragma once
// `duet import simulink FILE -o MODEL.yaml`: a Simulink model (.slx, .mdl) brought over as a duet model
// (docs/IMPORT.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_import_command(CLI::App& command);

}  // namespace duet::cli
