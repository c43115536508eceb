#pragma once
// The blocks that describe an MDF 4 file before its data: identification, header, file history, and every group's
// data group, channel group, channels, texts and conversions, laid out from offset 0 as one image.

#include <cstdint>
#include <string_view>
#include <vector>

#include "bytes.hpp"
#include "duet/mdf4/spec.hpp"

namespace duet::mdf4 {

// Where a group's records keep their values: the time first (f64 at 0), then each channel packed in order, then the
// invalidation bytes (value channel i is bit i).
struct RecordLayout {
  std::vector<ValueType> types;             // one per value channel, vectors expanded
  std::vector<std::uint32_t> byte_offsets;  // of each value channel within the record
  std::uint32_t data_bytes = 0;             // time and values
  std::uint32_t invalidation_bytes = 0;
  [[nodiscard]] std::uint32_t record_bytes() const { return data_bytes + invalidation_bytes; }
};

struct DescribedGroup {
  std::uint64_t dg_offset = 0;
  std::uint64_t cg_offset = 0;
  RecordLayout layout;
};

struct FileDescription {
  ByteBuffer image;  // ends 8-byte aligned
  std::vector<DescribedGroup> groups;
};

std::uint32_t size_of(ValueType type);

// `program_version`: duet's, named in the file history. `now_ns`: when the file is written (UTC).
FileDescription describe_file(const FileSpec& spec, std::string_view program_version, std::int64_t now_ns);

}  // namespace duet::mdf4
