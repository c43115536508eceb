#pragma once
// The `duet` subcommands, declared in one table (subcommands.cpp) from which the command line is built.

#include <functional>
#include <iosfwd>
#include <span>
#include <string_view>

namespace CLI {  // NOLINT(readability-identifier-naming): CLI11's namespace, declared here only
class App;
}

namespace duet::cli {

// duet's exit codes, documented in `duet --help` and docs/CLI.md.
enum class ExitCode : int { success = 0, failure = 1, usage = 2 };

struct Streams {
  std::ostream& out;
  std::ostream& err;
};

// What runs once the command line has parsed; the options it reads were bound when it was defined.
using Action = std::function<ExitCode(Streams)>;

struct Subcommand {
  std::string_view name;
  std::string_view summary;
  // Declares the subcommand's options on `command` and returns the action that runs it.
  Action (*define)(CLI::App& command);
};

std::span<const Subcommand> subcommands();

}  // namespace duet::cli
