#pragma once
// A file's version as duet studio compares them (docs/STUDIO.md): 16 hex digits of a 64-bit FNV-1a hash of its
// bytes. A save names the version it was edited from, so a file someone else changed is never overwritten.

#include <string>
#include <string_view>

namespace duet::studio {

[[nodiscard]] std::string version_of(std::string_view bytes);

}  // namespace duet::studio
