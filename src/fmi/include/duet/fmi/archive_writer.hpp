#pragma once
// Writing an FMU's zip archive: every entry deflated, names checked as the reader checks them (docs/FMI.md).

#include <filesystem>
#include <span>
#include <string>
#include <variant>

#include "duet/support/result.hpp"

namespace duet::fmi {

struct ArchiveInput {
  std::string name;                                          // in the archive, e.g. "binaries/x86_64-linux/Lag.so"
  std::variant<std::string, std::filesystem::path> content;  // the bytes themselves, or a file to take them from
};

// Writes `file` whole or not at all (libzip writes a temporary file and renames it).
[[nodiscard]] Status write_archive(const std::filesystem::path& file, std::span<const ArchiveInput> inputs);

}  // namespace duet::fmi
