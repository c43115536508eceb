#pragma once
// The import's options as a command line gives them: variables files (.m scripts of assignments or YAML), read in
// order so that later files see and replace earlier names, and interrupt mappings "PATH=IRQ:PRIORITY".

#include <string>
#include <utility>
#include <vector>

#include "duet/simulink_import/import.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

// Each file by its extension: .m a script (matlab_script.hpp), .yaml or .yml variables (yaml_variables.hpp).
[[nodiscard]] Result<Workspace> read_variable_files(const std::vector<std::string>& files);

// "model/Sub/ISR=TIM2:3" -> ("model/Sub/ISR", {TIM2, 3}); the path may hold '='; the last one separates.
[[nodiscard]] Result<std::pair<std::string, InterruptTask>> parse_interrupt_mapping(const std::string& text);

}  // namespace duet::simulink_import
