#pragma once
// `duet mdf`: describe an ASAM MDF 4 file and export its channels as CSV (docs/MDF4.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_mdf_command(CLI::App& command);

}  // namespace duet::cli
