#pragma once
// The MDF 4 block layouts duet writes and reads, as offsets from a block's start (docs/MDF4.md, "Layout"). All
// integers are little-endian; a link is an absolute file offset, 0 meaning none (NIL).

#include <cstddef>
#include <cstdint>

namespace duet::mdf4::format {

// The identification block: 64 bytes at offset 0, without the common header.
namespace id {
inline constexpr std::uint64_t size = 64;
inline constexpr std::uint64_t file_id = 0;  // "MDF     " finalised, "UnFinMF " not
inline constexpr std::uint64_t version_text = 8;
inline constexpr std::uint64_t program = 16;
inline constexpr std::uint64_t version_number = 28;
inline constexpr std::uint64_t unfinalised_flags = 60;
inline constexpr std::uint64_t custom_unfinalised_flags = 62;
inline constexpr std::uint16_t cycle_counts_flag = 0x01;  // the CG cycle counts are not up to date
inline constexpr std::uint16_t last_dt_length_flag = 0x04;
inline constexpr std::uint16_t last_dl_flag = 0x10;  // the last DL of a chain may end in NIL links
}  // namespace id

// Every other block: a 24-byte header (id, reserved, length, link count), the links, then the data section.
inline constexpr std::uint64_t header_size = 24;
inline constexpr std::uint64_t length_field = 8;
inline constexpr std::uint64_t link_count_field = 16;
inline constexpr std::uint64_t alignment = 8;
inline constexpr std::uint64_t hd_offset = 64;

inline constexpr std::uint64_t link(unsigned index) { return header_size + 8 * std::uint64_t{index}; }

namespace hd {  // header, 6 links
inline constexpr unsigned dg_first = 0, fh_first = 1, comment = 5, links = 6;
inline constexpr std::uint64_t start_time_ns = 72, size = 104;
}  // namespace hd
namespace fh {  // file history, 2 links
inline constexpr unsigned next = 0, comment = 1, links = 2;
inline constexpr std::uint64_t time_ns = 40, size = 56;
}  // namespace fh
namespace dg {  // data group, 4 links
inline constexpr unsigned next = 0, cg_first = 1, data = 2, comment = 3, links = 4;
inline constexpr std::uint64_t record_id_size = 56, size = 64;
}  // namespace dg
namespace cg {  // channel group, 6 links (the data section follows the links, so a seventh shifts it)
inline constexpr unsigned next = 0, cn_first = 1, acquisition_name = 2, comment = 5, links = 6;
// Data section, relative to its start (24 + 8 * links).
inline constexpr std::uint64_t record_id = 0, cycle_count = 8, flags = 16, data_bytes = 24, invalidation_bytes = 28,
                               data_size = 32;
}  // namespace cg
namespace cn {  // channel, 8 links
inline constexpr unsigned next = 0, name = 2, conversion = 4, unit = 6, comment = 7, links = 8;
// Data section, relative to its start.
inline constexpr std::uint64_t type = 0, sync_type = 1, data_type = 2, bit_offset = 3, byte_offset = 4, bit_count = 8,
                               flags = 12, invalidation_bit = 16, data_size = 72;
inline constexpr std::uint8_t fixed_length = 0, master = 2, virtual_master = 3, synchronisation = 4, virtual_data = 6;
inline constexpr std::uint8_t sync_time = 1;
inline constexpr std::uint32_t invalidation_bit_valid = 1u << 1;
}  // namespace cn
namespace data_type {
inline constexpr std::uint8_t unsigned_le = 0, unsigned_be = 1, signed_le = 2, signed_be = 3, float_le = 4,
                              float_be = 5;
}
namespace cc {  // conversion, 4 links then cc_ref_count more
inline constexpr unsigned links = 4;
// Data section, relative to its start.
inline constexpr std::uint64_t type = 0, ref_count = 4, value_count = 6, values = 24;
inline constexpr std::uint8_t identity = 0, linear = 1, value_to_text = 7;
}  // namespace cc
namespace dl {  // data list: next DL, then one link per data block
inline constexpr unsigned next = 0;
// Data section, relative to its start: flags, 3 reserved, count, then the offsets (or one equal length).
inline constexpr std::uint64_t flags = 0, count = 4;
}  // namespace dl
namespace hl {  // header list: 1 link to the first DL
inline constexpr unsigned dl_first = 0;
}

}  // namespace duet::mdf4::format
