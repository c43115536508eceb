#include "duet/xcp/memory_map.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace duet::xcp {
namespace {

TEST(MemoryMap, FindsOnlyWholeRangesInsideOneRegionWithTheRightAccess) {
  std::array<std::uint8_t, 16> measurements{};
  std::array<std::uint8_t, 8> parameters{};
  const std::array regions{
      MemoryRegion{.name = "signals", .address = 0x1000, .size = 16, .memory = measurements.data()},
      MemoryRegion{.name = "parameters",
                   .address = 0x2000,
                   .size = 8,
                   .memory = parameters.data(),
                   .access = Access::read_write},
  };
  const MemoryMap map{regions};

  EXPECT_EQ(map.find(0, 0x1000, 16, Access::read_only), measurements.data());
  EXPECT_EQ(map.find(0, 0x100C, 4, Access::read_only), measurements.data() + 12);
  EXPECT_EQ(map.find(0, 0x1010, 0, Access::read_only), measurements.data() + 16);  // empty, at the end
  EXPECT_EQ(map.find(0, 0x100D, 4, Access::read_only), nullptr);                   // one byte past the end
  EXPECT_EQ(map.find(0, 0x0FFF, 2, Access::read_only), nullptr);                   // one byte before the start
  EXPECT_EQ(map.find(0, 0x1000, 4, Access::read_write), nullptr);                  // measurements are read-only
  EXPECT_EQ(map.find(0, 0x2004, 4, Access::read_write), parameters.data() + 4);
  EXPECT_EQ(map.find(1, 0x2004, 4, Access::read_write), nullptr);           // another address extension
  EXPECT_EQ(map.find(0, 0x2004, 0xFFFF'FFFF, Access::read_only), nullptr);  // size that would wrap
  EXPECT_EQ(map.find(0, 0xFFFF'FFFF, 2, Access::read_only), nullptr);
}

}  // namespace
}  // namespace duet::xcp
