#pragma once
// Any Simulink model file, whatever its extension says: an .slx (a zip), a packaged text .mdl (R2023a or so on) or a
// classic .mdl, told apart by their bytes as MATLAB's own readers do.

#include <filesystem>

#include "duet/simulink_import/simulink_model.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

[[nodiscard]] Result<SimulinkModel> read_simulink_file(const std::filesystem::path& file);

}  // namespace duet::simulink_import
