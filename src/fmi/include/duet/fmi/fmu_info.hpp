#pragma once
// What `duet fmu info` tells of an FMU: its description, the platforms it has binaries for, and whether the one
// duet would load is there (docs/FMI.md).

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "duet/fmi/model_description.hpp"
#include "duet/support/result.hpp"

namespace duet::fmi {

struct FmuInfo {
  ModelDescription description;
  std::vector<std::string> platforms;  // the folders under binaries/, e.g. "linux64", "x86_64-linux"
  std::string linux_binary;            // where this version keeps the Linux x86_64 library, in the archive
  bool has_linux_binary = false;
};

[[nodiscard]] Result<FmuInfo> read_fmu_info(const std::filesystem::path& file);
void write_text(std::ostream& out, const FmuInfo& info);
[[nodiscard]] std::string to_json(const FmuInfo& info);  // one object, for scripts

}  // namespace duet::fmi
