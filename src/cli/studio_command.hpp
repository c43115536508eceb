#pragma once
// duet studio: a model in the browser, its diagram beside its text (docs/STUDIO.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_studio_command(CLI::App& command);

}  // namespace duet::cli
