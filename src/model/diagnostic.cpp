#include "duet/model/diagnostic.hpp"

#include <algorithm>

namespace duet::model {

std::string format(const std::string& file, const Diagnostic& diagnostic) {
  const std::string& where = diagnostic.location.file.empty() ? file : diagnostic.location.file;
  std::string text =
      where + ":" + std::to_string(diagnostic.location.line) + ":" + std::to_string(diagnostic.location.column) + ": " +
      (diagnostic.severity == Diagnostic::Severity::error ? "error: " : "warning: ") + diagnostic.message;
  if (!diagnostic.hint.empty()) text += " (" + diagnostic.hint + ")";
  return text;
}

bool has_errors(const std::vector<Diagnostic>& diagnostics) {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return d.severity == Diagnostic::Severity::error; });
}

}  // namespace duet::model
