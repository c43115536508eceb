#include "duet/xcp/checksum.hpp"

namespace duet::xcp {
namespace {

std::uint32_t sum_of_little_endian(std::span<const std::uint8_t> bytes, std::size_t width) {
  std::uint32_t sum = 0;
  for (std::size_t offset = 0; offset + width <= bytes.size(); offset += width) {
    std::uint32_t value = 0;
    for (std::size_t byte = 0; byte < width; ++byte)
      value |= static_cast<std::uint32_t>(bytes[offset + byte]) << (8U * byte);
    sum += value;
  }
  return sum;
}

// CRC-16/ARC: polynomial 0x8005 reflected (0xA001), initial 0, no final XOR.
std::uint32_t crc_16_arc(std::span<const std::uint8_t> bytes) {
  std::uint16_t crc = 0;
  for (std::uint8_t byte : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ byte);
    for (int bit = 0; bit < 8; ++bit)
      crc = static_cast<std::uint16_t>((crc & 1U) != 0 ? (crc >> 1) ^ 0xA001U : crc >> 1);
  }
  return crc;
}

std::uint32_t crc_16_ccitt(std::span<const std::uint8_t> bytes) {
  std::uint16_t crc = 0xFFFF;
  for (std::uint8_t byte : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ (static_cast<std::uint16_t>(byte) << 8));
    for (int bit = 0; bit < 8; ++bit) {
      const auto shifted = static_cast<std::uint16_t>(crc << 1U);
      crc = (crc & 0x8000U) != 0 ? static_cast<std::uint16_t>(shifted ^ 0x1021U) : shifted;
    }
  }
  return crc;
}

// CRC-32 as zlib: polynomial 0x04C11DB7 reflected (0xEDB88320), initial and final XOR 0xFFFFFFFF.
std::uint32_t crc_32(std::span<const std::uint8_t> bytes) {
  std::uint32_t crc = 0xFFFF'FFFF;
  for (std::uint8_t byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc & 1U) != 0 ? (crc >> 1) ^ 0xEDB8'8320U : crc >> 1;
  }
  return ~crc;
}

}  // namespace

std::uint32_t checksum(ChecksumType type, std::span<const std::uint8_t> bytes) {
  switch (type) {
    case ChecksumType::add_11: return sum_of_little_endian(bytes, 1) & 0xFFU;
    case ChecksumType::add_12: return sum_of_little_endian(bytes, 1) & 0xFFFFU;
    case ChecksumType::add_14: return sum_of_little_endian(bytes, 1);
    case ChecksumType::add_22: return sum_of_little_endian(bytes, 2) & 0xFFFFU;
    case ChecksumType::add_24: return sum_of_little_endian(bytes, 2);
    case ChecksumType::add_44: return sum_of_little_endian(bytes, 4);
    case ChecksumType::crc_16: return crc_16_arc(bytes);
    case ChecksumType::crc_16_ccitt: return crc_16_ccitt(bytes);
    case ChecksumType::crc_32: return crc_32(bytes);
  }
  return 0;
}

}  // namespace duet::xcp
