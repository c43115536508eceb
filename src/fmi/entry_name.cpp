#include "entry_name.hpp"

namespace duet::fmi {

std::optional<std::string> entry_name_problem(std::string_view name) {
  if (name.empty()) return "empty name";
  if (name.front() == '/') return "absolute path";
  if (name.find('\\') != std::string_view::npos) return "backslash in the name (FMUs separate folders with '/')";
  if (name.find('\0') != std::string_view::npos) return "NUL character in the name";
  std::string_view rest = name;
  if (rest.back() == '/') rest.remove_suffix(1);  // a folder's entry
  while (true) {
    const std::size_t slash = rest.find('/');
    const std::string_view component = rest.substr(0, slash);
    if (component == "..") return "'..' in the path (it would leave the folder it is unpacked into)";
    if (component.empty() || component == ".") return "empty or '.' component in the path";
    if (slash == std::string_view::npos) return std::nullopt;
    rest.remove_prefix(slash + 1);
  }
}

}  // namespace duet::fmi
