#pragma once
// `duet plant serve NAME`: a simulated plant in a process of its own, served over the virtual-hardware link to
// firmware that connects over TCP (docs/LINK.md), its own quantities recorded per TICK as CSV and plot if asked.

#include "subcommand.hpp"

namespace duet::cli {

Action define_plant_command(CLI::App& command);

}  // namespace duet::cli
