#pragma once
// `duet sim MODEL --plant NAME --duration S`: simulates a model on the PC and writes CSV and an SVG plot.

#include "subcommand.hpp"

namespace duet::cli {

Action define_sim_command(CLI::App& command);

}  // namespace duet::cli
