#pragma once
// `duet fmu`: FMI co-simulation FMUs; `duet fmu info` describes one, `duet fmu export` makes one of a model
// (docs/FMI.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_fmu_command(CLI::App& command);

}  // namespace duet::cli
