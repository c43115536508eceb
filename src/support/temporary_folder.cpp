#include "duet/support/temporary_folder.hpp"

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

namespace duet {

Result<TemporaryFolder> TemporaryFolder::make(std::string_view prefix) {
  std::error_code error;
  const std::filesystem::path base = std::filesystem::temp_directory_path(error);
  if (error) return Failure{"no temporary folder: " + error.message()};
  std::string pattern = (base / (std::string{prefix} + "XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr)
    return Failure{"cannot make a folder " + pattern + ": " + std::strerror(errno)};
  return TemporaryFolder{pattern};
}

TemporaryFolder::~TemporaryFolder() {
  if (path_.empty()) return;
  std::error_code ignored;  // a folder that cannot be removed is left behind, nothing worse
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace duet
