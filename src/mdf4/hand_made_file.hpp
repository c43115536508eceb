#pragma once
// MDF 4 files built byte by byte in tests, as other writers lay them out: blocks appended 8-byte aligned, their
// fields put at offsets written out from the format's tables (docs/MDF4.md), independently of duet's writer.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace duet::mdf4::testing {

class HandMadeFile {
 public:
  // The 64-byte identification block: "MDF     " or "UnFinMF ", the version, the unfinalised flags.
  explicit HandMadeFile(std::string_view file_id = "MDF     ", std::string_view version = "4.20    ",
                        std::uint16_t version_number = 420, std::uint16_t unfinalised_flags = 0) {
    text(file_id);
    text(version);
    text("other   ");
    bytes.resize(64, 0);
    put<std::uint16_t>(28, version_number);
    put<std::uint16_t>(60, unfinalised_flags);
  }

  // A block with the common header, `links` zero links and `data_size` zero bytes of data, 8-byte aligned.
  std::size_t block(std::string_view id, std::size_t links, std::size_t data_size, bool align = true) {
    if (align) bytes.resize((bytes.size() + 7) / 8 * 8, 0);
    const std::size_t at = bytes.size();
    text(id);
    bytes.resize(at + 24 + 8 * links + data_size, 0);
    put<std::uint64_t>(at + 8, 24 + 8 * links + data_size);
    put<std::uint64_t>(at + 16, links);
    return at;
  }
  // A text block, zero-terminated; `padded`: its length rounded up to 8 as asammdf writes it, else 24 + size + 1.
  std::size_t tx(std::string_view content, std::string_view id = "##TX", bool padded = true) {
    const std::size_t size = padded ? (content.size() + 8) / 8 * 8 : content.size() + 1;
    const std::size_t at = block(id, 0, size);
    std::memcpy(bytes.data() + at + 24, content.data(), content.size());
    return at;
  }
  template <typename T>
  void put(std::size_t at, T value) {
    std::memcpy(bytes.data() + at, &value, sizeof value);
  }
  void link(std::size_t block, unsigned index, std::uint64_t target) {
    put<std::uint64_t>(block + 24 + 8 * std::size_t{index}, target);
  }
  template <typename T>
  T get(std::size_t at) const {
    T value;
    std::memcpy(&value, bytes.data() + at, sizeof value);
    return value;
  }
  void append_raw(const void* data, std::size_t size) {
    const std::size_t at = bytes.size();
    bytes.resize(at + size);
    if (size > 0) std::memcpy(bytes.data() + at, data, size);
  }

  // HD at 64 (6 links, 104 bytes), returning its offset.
  std::size_t header() { return block("##HD", 6, 32); }
  // DG: 4 links, record id size at 56.
  std::size_t data_group(std::uint8_t record_id_size = 0) {
    const std::size_t at = block("##DG", 4, 8);
    put<std::uint8_t>(at + 56, record_id_size);
    return at;
  }
  // CG: 6 links (7 with 4.2's remote master), then record id, cycle count, flags, ..., data bytes, invalidation bytes.
  std::size_t channel_group(std::uint64_t record_id, std::uint64_t cycles, std::uint32_t data_bytes,
                            std::uint32_t invalidation_bytes, unsigned links = 6) {
    const std::size_t at = block("##CG", links, 32);
    const std::size_t data = at + 24 + 8 * std::size_t{links};
    put<std::uint64_t>(data, record_id);
    put<std::uint64_t>(data + 8, cycles);
    put<std::uint32_t>(data + 24, data_bytes);
    put<std::uint32_t>(data + 28, invalidation_bytes);
    return at;
  }
  // CN: 8 links, data at 88: type, sync, data type, bit offset, byte offset, bit count, flags, invalidation bit.
  std::size_t channel(std::string_view name, std::uint8_t type, std::uint8_t data_type, std::uint32_t byte_offset,
                      std::uint32_t bit_count, std::uint8_t bit_offset = 0) {
    const std::size_t at = block("##CN", 8, 72);
    put<std::uint8_t>(at + 88, type);
    put<std::uint8_t>(at + 89, type == 2 || type == 3 ? 1 : 0);
    put<std::uint8_t>(at + 90, data_type);
    put<std::uint8_t>(at + 91, bit_offset);
    put<std::uint32_t>(at + 92, byte_offset);
    put<std::uint32_t>(at + 96, bit_count);
    link(at, 2, tx(name));
    return at;
  }
  std::size_t data_block(const std::vector<std::uint8_t>& records) {
    const std::size_t at = block("##DT", 0, records.size());
    if (!records.empty()) std::memcpy(bytes.data() + at + 24, records.data(), records.size());
    return at;
  }

  std::vector<std::uint8_t> bytes;

 private:
  void text(std::string_view content) {
    const std::size_t at = bytes.size();
    bytes.resize(at + content.size());
    std::memcpy(bytes.data() + at, content.data(), content.size());
  }
};

// Records from values laid out by hand.
class RecordBytes {
 public:
  template <typename T>
  RecordBytes& add(T value) {
    const std::size_t at = bytes.size();
    bytes.resize(at + sizeof value);
    std::memcpy(bytes.data() + at, &value, sizeof value);
    return *this;
  }
  std::vector<std::uint8_t> bytes;
};

}  // namespace duet::mdf4::testing
