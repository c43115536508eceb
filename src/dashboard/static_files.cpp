#include "duet/dashboard/static_files.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace duet::dashboard {

Result<std::filesystem::path> file_for(const std::filesystem::path& root, std::string_view target) {
  target = target.substr(0, target.find('?'));
  if (target.empty() || target.front() != '/') return Failure{"a target starts with /"};
  target.remove_prefix(1);
  std::string name = target.empty() ? std::string{"index.html"} : std::string{target};
  const bool plain = std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
           c == '-' || c == '/';
  });
  if (!plain || name.front() == '/') return Failure{"not a plain file name"};  // "//x" would be absolute
  for (const auto& part : std::filesystem::path{name}) {
    if (part.empty() || part.string().front() == '.') return Failure{"no hidden files or parent folders"};
  }
  std::filesystem::path file = root / name;
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return Failure{"no such file"};
  return file;
}

std::filesystem::path default_web_root() {
  std::error_code error;
  const auto program = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const auto installed = program.parent_path().parent_path() / "share" / "duet" / "web";
    if (std::filesystem::is_directory(installed, error)) return installed;
  }
#ifdef DUET_SOURCE_WEB_ROOT
  if (std::filesystem::is_directory(DUET_SOURCE_WEB_ROOT, error)) return DUET_SOURCE_WEB_ROOT;
#endif
  return {};
}

std::string_view content_type(const std::filesystem::path& file) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 9> types{{
      {".html", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},
      {".map", "application/json"},
      {".svg", "image/svg+xml"},
      {".png", "image/png"},
      {".ico", "image/x-icon"},
      {".txt", "text/plain; charset=utf-8"},
  }};
  const std::string extension = file.extension().string();
  for (const auto& [suffix, type] : types) {
    if (extension == suffix) return type;
  }
  return "application/octet-stream";
}

}  // namespace duet::dashboard
