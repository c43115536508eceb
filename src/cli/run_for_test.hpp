#pragma once
// Runs the duet command line in-process for tests and keeps what it printed.

#include <sstream>
#include <string>
#include <vector>

#include "command_line.hpp"

namespace duet::cli {

struct Outcome {
  ExitCode exit_code;
  std::string out;
  std::string err;
};

inline Outcome run(const std::vector<std::string>& arguments) {
  std::ostringstream out;
  std::ostringstream err;
  const ExitCode exit_code = run_command_line(arguments, {out, err});
  return {exit_code, out.str(), err.str()};
}

}  // namespace duet::cli
