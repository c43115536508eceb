#pragma once
// The classic .mdl reader: the nested-brace text Simulink wrote up to R2019b (`Model { ... }`), read into a
// SimulinkModel without MATLAB. docs/IMPORT.md, "Classic .mdl files", says what is read and what is refused.

#include <string>
#include <string_view>

#include "duet/simulink_import/simulink_model.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

// `bytes` is the whole file, `file` its name for messages ("model.mdl:12: ..."). Refuses block libraries, encodings
// other than ISO-8859-1, windows-1252 and UTF-8, and damaged files, naming the line and the problem.
Result<SimulinkModel> read_classic_mdl(std::string_view bytes, const std::string& file);

}  // namespace duet::simulink_import
