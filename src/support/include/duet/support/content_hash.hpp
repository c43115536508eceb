#pragma once
// A short name for some bytes: 16 hex digits of their 64-bit FNV-1a hash. duet studio's file versions (a save names
// the version it was edited from, so a file someone else changed is never overwritten) and the EPK that ties a
// generated A2L to the firmware built with it.

#include <string>
#include <string_view>

namespace duet {

[[nodiscard]] std::string content_hash(std::string_view bytes);

}  // namespace duet
