#pragma once
// The PC's C++ compiler, run as a child process: what builds a model's Code blocks for `duet sim` and an exported
// FMU's library (`duet fmu export`).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"

namespace duet {

// The compiler's command: $CXX, or c++ when it is not set.
[[nodiscard]] std::string cxx_compiler();

// Runs `command` (the compiler first), its output going to the file `messages`. Fails with "the C++ compiler
// '...' was not found (set CXX)", or with "`what` did not compile:" and the compiler's output.
[[nodiscard]] Status compile(std::vector<std::string> command, const std::filesystem::path& messages,
                             std::string_view what);

}  // namespace duet
