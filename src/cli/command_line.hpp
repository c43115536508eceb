#pragma once
// The `duet` command line: parses the arguments, runs the chosen subcommand and returns the process exit code.

#include <span>
#include <string>

#include "subcommand.hpp"

namespace duet::cli {

// `arguments` excludes the program name. Usage errors print one line naming the offending word to `streams.err`
// and return ExitCode::usage; --help and --version print to `streams.out` and return ExitCode::success.
ExitCode run_command_line(std::span<const std::string> arguments, Streams streams);

}  // namespace duet::cli
