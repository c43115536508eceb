#pragma once
// A Simulink model from the parts of its package (slx_parts.hpp): the block diagram of either layout era (the
// whole tree in simulink/blockdiagram.xml up to R2019b, one simulink/systems/system_N.xml per subsystem from
// R2020a), port counts old (Ports) and new (PortCounts, R2022b), masks of each era, library links' values, lines
// with their branches, BlockParameterDefaults where the file has them, the active configuration set's solver and
// the release that saved it. docs/IMPORT.md, "Reading .slx files".

#include <string>

#include "duet/simulink_import/simulink_model.hpp"
#include "duet/simulink_import/slx_parts.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

// `file` names the package in messages: "model.slx: simulink/systems/system_3.xml:12: ...".
[[nodiscard]] Result<SimulinkModel> read_slx_model(const Parts& parts, const std::string& file);

}  // namespace duet::simulink_import
