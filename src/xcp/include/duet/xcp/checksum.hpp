#pragma once
// BUILD_CHECKSUM's algorithms over a block of memory. Freestanding; each is a fold over the bytes, so a block can be
// fed in pieces.

#include <cstddef>
#include <cstdint>
#include <span>

namespace duet::xcp {

// The checksum type byte of BUILD_CHECKSUM's response.
enum class ChecksumType : std::uint8_t {
  add_11 = 0x01,        // sum of bytes into a byte
  add_12 = 0x02,        // sum of bytes into a word
  add_14 = 0x03,        // sum of bytes into a double word
  add_22 = 0x04,        // sum of little-endian words into a word
  add_24 = 0x05,        // sum of little-endian words into a double word
  add_44 = 0x06,        // sum of little-endian double words into a double word
  crc_16 = 0x07,        // CRC-16/ARC
  crc_16_ccitt = 0x08,  // polynomial 0x1021, initial 0xFFFF, not reflected
  crc_32 = 0x09,        // as zlib's
};

// The checksum of `bytes` of one type. ADD_22/24 need a length that is a multiple of 2, ADD_44 of 4; the caller
// (BUILD_CHECKSUM) refuses other lengths with ERR_OUT_OF_RANGE.
std::uint32_t checksum(ChecksumType type, std::span<const std::uint8_t> bytes);

}  // namespace duet::xcp
