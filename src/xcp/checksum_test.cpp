#include "duet/xcp/checksum.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace duet::xcp {
namespace {

// A 32-byte test vector whose checksums the XCP standard's checksum table gives: 01 02 .. 10, then F1 F2 .. FF, then
// 00.
std::vector<std::uint8_t> test_vector() {
  std::vector<std::uint8_t> bytes;
  for (int value = 0x01; value <= 0x10; ++value) bytes.push_back(static_cast<std::uint8_t>(value));
  for (int value = 0xF1; value <= 0xFF; ++value) bytes.push_back(static_cast<std::uint8_t>(value));
  bytes.push_back(0x00);
  return bytes;
}

TEST(Checksum, MatchesTheStandardsTestVectors) {
  const std::vector<std::uint8_t> bytes = test_vector();
  ASSERT_EQ(bytes.size(), 32U);
  EXPECT_EQ(checksum(ChecksumType::add_11, bytes), 0x10U);
  EXPECT_EQ(checksum(ChecksumType::add_22, bytes), 0x1800U);
  EXPECT_EQ(checksum(ChecksumType::add_44, bytes), 0x140C'03F8U);
  EXPECT_EQ(checksum(ChecksumType::crc_16, bytes), 0xC76AU);
  EXPECT_EQ(checksum(ChecksumType::crc_16_ccitt, bytes), 0x9D50U);
  EXPECT_EQ(checksum(ChecksumType::crc_32, bytes), 0x89CD'97CEU);
}

TEST(Checksum, ByteSumsOfOtherWidthsKeepTheirCarries) {
  const std::vector<std::uint8_t> bytes = test_vector();
  // 1 + .. + 16 = 136, 0xF1 + .. + 0xFF = 3720: 3856 = 0x0F10, of which ADD_11 keeps the low byte 0x10.
  EXPECT_EQ(checksum(ChecksumType::add_12, bytes), 0x0F10U);
  EXPECT_EQ(checksum(ChecksumType::add_14, bytes), 0x0F10U);
  EXPECT_EQ(checksum(ChecksumType::add_24, std::vector<std::uint8_t>{0xFF, 0xFF, 0xFF, 0xFF}), 0x1'FFFEU);
}

TEST(Checksum, EmptyBlocks) {
  EXPECT_EQ(checksum(ChecksumType::add_44, {}), 0U);
  EXPECT_EQ(checksum(ChecksumType::crc_16_ccitt, {}), 0xFFFFU);
  EXPECT_EQ(checksum(ChecksumType::crc_32, {}), 0U);
}

}  // namespace
}  // namespace duet::xcp
