#pragma once
// `duet xcp`: talk XCP to a slave from the command line (see docs/XCP.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_xcp_command(CLI::App& command);

}  // namespace duet::cli
