#pragma once
// Checks an A2L file against the rules of ASAP2 1.71 and of XCP's IF_DATA, strictly: keywords in the blocks that may
// hold them, every value present and of its type and range, names unique and references that resolve, addresses in
// declared memory, the EPK where a master can read it. Keywords it does not know are warnings, not silence.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace duet::xcp::host {

struct A2lProblem {
  enum class Severity : std::uint8_t { error, warning };
  Severity severity = Severity::error;
  std::string place;  // FILE:LINE:COLUMN
  std::string message;
  [[nodiscard]] std::string text() const;  // "FILE:LINE:COLUMN: error: message"
  bool operator==(const A2lProblem&) const = default;
};

// The problems in A2L text, in the order of the file; `source` names it in places, and /include looks in its folder.
std::vector<A2lProblem> check_a2l(std::string_view text, std::string_view source);
// The same for a file (one that cannot be read is one error).
std::vector<A2lProblem> check_a2l_file(const std::string& path);
bool has_errors(const std::vector<A2lProblem>& problems);

}  // namespace duet::xcp::host
