#pragma once
// What an MDF 4 file holds, as `duet mdf info` prints it: version, writer, finalised or recovered, start, and per
// group its samples, time span and channels with type, unit, conversion and comment.

#include <string>

#include "duet/mdf4/reader.hpp"
#include "duet/support/result.hpp"

namespace duet::mdf4 {

Result<std::string> summarise(const Reader& reader);
// A channel's stored type in short: "u16", "i5 at bit 3", "f64 big-endian", "string (not decoded)".
std::string type_text(const ChannelInfo& channel);

}  // namespace duet::mdf4
