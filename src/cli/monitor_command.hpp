#pragma once
// duet monitor: the dashboard for a target reached over XCP (docs/DASHBOARD.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_monitor_command(CLI::App& command);

}  // namespace duet::cli
