#pragma once
// A classic .mdl `System { Block {...} Line {...} }` section into a System: blocks with their parameters, masks and
// nested systems; lines with their branches flattened and their ends checked against the system's blocks.

#include <string>

#include "duet/simulink_import/simulink_model.hpp"
#include "duet/support/result.hpp"
#include "mdl_syntax.hpp"

namespace duet::simulink_import {

// `path` names the system in messages ("model/Controller"); `file` is the .mdl file, which becomes System::part.
Result<System> read_mdl_system(const MdlNode& section, const std::string& path, const std::string& file);

}  // namespace duet::simulink_import
