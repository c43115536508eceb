#pragma once
// `duet gen MODEL -o DIR`: freestanding C++, the A2L and a CMake fragment from a model.

#include "subcommand.hpp"

namespace duet::cli {

Action define_gen_command(CLI::App& command);

}  // namespace duet::cli
