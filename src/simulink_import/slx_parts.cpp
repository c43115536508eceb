#include "duet/simulink_import/slx_parts.hpp"

#include <algorithm>

#include "duet/fmi/archive.hpp"

namespace duet::simulink_import {
namespace {

constexpr std::string_view package_begin = "__MWOPC_PACKAGE_BEGIN__";
constexpr std::string_view package_end = "__MWOPC_PACKAGE_END__";
constexpr std::string_view part_begin = "__MWOPC_PART_BEGIN__";

bool is_text_part(std::string_view name) { return name.ends_with(".xml") || name.ends_with(".json"); }

}  // namespace

Result<Parts> read_slx_parts(const std::filesystem::path& file) {
  auto archive = fmi::Archive::open(file);
  if (!archive) return Failure{archive.error()};
  Parts parts;
  for (const fmi::ArchiveEntry& entry : archive.value().entries()) {
    if (entry.name.ends_with('/') || !is_text_part(entry.name)) continue;
    auto bytes = archive.value().read(entry.name);
    if (!bytes) return Failure{bytes.error()};
    parts.emplace(entry.name, std::move(bytes).value());
  }
  return parts;
}

bool is_packaged_mdl(std::string_view bytes) {
  return bytes.substr(0, 4096).find(package_begin) != std::string_view::npos;
}

// Markers count only at the start of a line; the newline before a marker belongs to the framing, not to the part.
Result<Parts> read_packaged_mdl_parts(std::string_view bytes, const std::string& file) {
  Parts parts;
  std::string current;  // the part being read, or empty before the first
  std::string text;
  bool ended = false;
  int line_number = 0;
  const auto finish_part = [&] {
    if (!current.empty()) parts.insert_or_assign(current, std::move(text));
    text.clear();
  };
  bool begun = false;
  for (std::size_t start = 0; start < bytes.size() && !ended;) {
    const std::size_t newline = std::min(bytes.find('\n', start), bytes.size());
    const std::string_view line = bytes.substr(start, newline - start);
    ++line_number;
    const std::string where = file + ":" + std::to_string(line_number) + ": ";
    if (line.starts_with(package_begin)) {
      begun = true;
    } else if (line.starts_with(package_end)) {
      finish_part();
      current.clear();
      ended = true;
    } else if (line.starts_with(part_begin)) {
      if (!begun) return Failure{where + "a part before " + std::string{package_begin}};
      finish_part();
      std::string_view name = line.substr(part_begin.size());
      while (name.starts_with(' ')) name.remove_prefix(1);
      if (name.ends_with('\r')) name.remove_suffix(1);
      const std::size_t space = name.find(' ');  // "NAME BASE64" marks a binary part
      const bool binary = space != std::string_view::npos;
      name = name.substr(0, space);
      if (!name.starts_with('/') || name.size() < 2) return Failure{where + "a part without a name ('/...')"};
      name.remove_prefix(1);
      current = binary || !is_text_part(name) ? std::string{} : std::string{name};
      if (!current.empty() && parts.count(current) != 0) return Failure{where + "part /" + current + " twice"};
    } else if (!current.empty()) {
      if (!text.empty()) text += '\n';
      text += line;
    }
    start = newline + 1;
  }
  if (!begun) return Failure{file + ": not a packaged text model (no " + std::string{package_begin} + ")"};
  if (!ended) return Failure{file + ": the package ends without " + std::string{package_end} + " (truncated?)"};
  return parts;
}

}  // namespace duet::simulink_import
