#pragma once
// `duet a2l check FILE...`: checks A2L files against ASAP2 1.71 and XCP's IF_DATA (docs/XCP.md, "Checking an A2L").

#include "subcommand.hpp"

namespace duet::cli {

Action define_a2l_command(CLI::App& command);

}  // namespace duet::cli
