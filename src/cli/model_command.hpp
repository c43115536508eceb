#pragma once
// `duet model`: check a model file and show its tasks; draw its block diagram (docs/MODELS.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_model_command(CLI::App& command);

}  // namespace duet::cli
