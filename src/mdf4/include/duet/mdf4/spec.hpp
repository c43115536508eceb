#pragma once
// What an MDF4 file written by duet holds: its groups (one per sampling event or rate), their channels with exact
// types, names, units, comments and linear conversions (docs/MDF4.md).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace duet::mdf4 {

// A channel's stored type. `boolean` is stored as an unsigned 8-bit integer holding 0 or 1 (MDF has no boolean).
enum class ValueType : std::uint8_t { boolean, u8, u16, u32, u64, i8, i16, i32, i64, f32, f64 };

// physical = factor * stored + offset (MDF's linear conversion, CC type 1).
struct Linear {
  double factor = 1;
  double offset = 0;
};

struct ChannelSpec {
  std::string name;
  ValueType type = ValueType::f64;
  std::string unit;
  std::string comment;
  std::optional<Linear> conversion;
  // A vector signal of `elements` values is written as that many channels, `name[0]` to `name[elements - 1]`.
  std::size_t elements = 1;
};

// One data group: its own time channel ("time", seconds since FileSpec::start_time_ns, f64) and these channels.
struct GroupSpec {
  std::string name;  // the acquisition name, e.g. the XCP event or the rate
  std::string comment;
  std::vector<ChannelSpec> channels;
};

struct FileSpec {
  std::vector<GroupSpec> groups;
  std::int64_t start_time_ns = 0;  // the recording's start, nanoseconds since 1970-01-01 00:00 UTC
  std::string comment;             // the file's comment (empty: none)
};

}  // namespace duet::mdf4
