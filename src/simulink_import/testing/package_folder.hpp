#pragma once
// The tests' Simulink packages are folders of their parts (testing/slx_r2019b, ...): read as the zip would hold them.

#include <filesystem>

#include "duet/simulink_import/slx_parts.hpp"
#include "duet/support/text_file.hpp"

namespace duet::simulink_import {

inline Parts parts_of(const std::filesystem::path& folder) {
  Parts parts;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    parts[std::filesystem::relative(entry.path(), folder).generic_string()] =
        read_text_file(entry.path().string()).value();
  }
  return parts;
}

}  // namespace duet::simulink_import
