#pragma once
// Zip archives written byte by byte, so that tests can make what no zip library would: duplicate names, links,
// encryption flags, foreign compression methods, sizes that lie. Entries are stored, not compressed.

#include <cstdint>
#include <string>
#include <vector>

namespace duet::fmi::testing {

struct HandMadeEntry {
  std::string name;
  std::string bytes;
  std::uint16_t method = 0;           // 0 store; anything else is only claimed
  std::uint16_t flags = 0;            // bit 0: encrypted
  std::uint32_t unix_mode = 0100644;  // st_mode: a regular file; 0120777 a symbolic link
  std::uint32_t claimed_size = 0;     // the unpacked size in the headers when not 0
};

inline std::uint32_t crc32_of(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char byte : bytes) {
    crc ^= static_cast<std::uint8_t>(byte);
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

inline std::string hand_made_zip(const std::vector<HandMadeEntry>& entries) {
  std::string archive;
  std::string directory;
  auto put = [](std::string& to, std::uint32_t value, int bytes) {
    for (int i = 0; i < bytes; ++i) to += static_cast<char>((value >> (8 * i)) & 0xFFu);
  };
  for (const HandMadeEntry& entry : entries) {
    const auto offset = static_cast<std::uint32_t>(archive.size());
    const auto size = static_cast<std::uint32_t>(entry.bytes.size());
    const std::uint32_t claimed = entry.claimed_size != 0 ? entry.claimed_size : size;
    const auto name_length = static_cast<std::uint32_t>(entry.name.size());
    auto common = [&](std::string& to) {  // from "version needed" to "extra length", alike in both headers
      put(to, 20, 2);
      put(to, entry.flags, 2);
      put(to, entry.method, 2);
      put(to, 0, 4);  // time and date
      put(to, crc32_of(entry.bytes), 4);
      put(to, size, 4);
      put(to, claimed, 4);
      put(to, name_length, 2);
      put(to, 0, 2);
    };
    put(archive, 0x04034b50, 4);
    common(archive);
    archive += entry.name + entry.bytes;
    put(directory, 0x02014b50, 4);
    put(directory, 0x0314, 2);  // made by Unix (3), zip 2.0
    common(directory);
    put(directory, 0, 2);  // comment length
    put(directory, 0, 2);  // disk
    put(directory, 0, 2);  // internal attributes
    put(directory, entry.unix_mode << 16, 4);
    put(directory, offset, 4);
    directory += entry.name;
  }
  const auto directory_offset = static_cast<std::uint32_t>(archive.size());
  archive += directory;
  put(archive, 0x06054b50, 4);
  put(archive, 0, 4);  // disks
  put(archive, static_cast<std::uint32_t>(entries.size()), 2);
  put(archive, static_cast<std::uint32_t>(entries.size()), 2);
  put(archive, static_cast<std::uint32_t>(directory.size()), 4);
  put(archive, directory_offset, 4);
  put(archive, 0, 2);  // comment length
  return archive;
}

}  // namespace duet::fmi::testing
