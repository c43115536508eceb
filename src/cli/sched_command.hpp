#pragma once
// `duet sched`: schedulability analysis of an interrupt task set, and NVIC priority assignment (docs/SCHEDULING.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_sched_command(CLI::App& command);

}  // namespace duet::cli
