#pragma once
// The parts of a Simulink package, by name ("simulink/blockdiagram.xml"), from either container that holds them: an
// .slx zip archive (Open Packaging Conventions) or a packaged text .mdl, which carries the same parts as text
// between "__MWOPC_PART_BEGIN__ /NAME" markers. Only the text parts the importer reads are kept (XML and JSON);
// binary parts (MAT data, thumbnails) are left out.

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "duet/support/result.hpp"

namespace duet::simulink_import {

using Parts = std::map<std::string, std::string, std::less<>>;

// An .slx file, with the archive checks duet applies to every zip it opens (no entry outside the package, no
// entry bigger than its header says).
[[nodiscard]] Result<Parts> read_slx_parts(const std::filesystem::path& file);

// Whether `bytes` are a packaged text .mdl: the marker in its first 4 KB, as MATLAB writes it.
[[nodiscard]] bool is_packaged_mdl(std::string_view bytes);

// A packaged text .mdl's parts; `file` names it in messages ("model.mdl:LINE: ...").
[[nodiscard]] Result<Parts> read_packaged_mdl_parts(std::string_view bytes, const std::string& file);

}  // namespace duet::simulink_import
