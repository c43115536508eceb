#pragma once
// What validation says about a model: where, what, and a hint, as `file:line:column: error: what (hint)`.

#include <string>
#include <vector>

#include "duet/model/model.hpp"

namespace duet::model {

struct Diagnostic {
  enum class Severity { error, warning } severity = Severity::error;
  Location location;
  std::string message;
  std::string hint;
};

[[nodiscard]] std::string format(const std::string& file, const Diagnostic& diagnostic);
[[nodiscard]] bool has_errors(const std::vector<Diagnostic>& diagnostics);

}  // namespace duet::model
