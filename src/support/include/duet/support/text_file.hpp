#pragma once
// A whole text file read at once, for the readers of model, task-set and A2L files.

#include <fstream>
#include <sstream>
#include <string>

#include "duet/support/result.hpp"

namespace duet {

inline Result<std::string> read_text_file(const std::string& path) {
  std::ifstream in{path};
  if (!in) return Failure{path + ": cannot open"};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace duet
