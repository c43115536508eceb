// Peripheral clocks against a fake register file: one store of one bit to the right MC_xxxENSETR register each, so
// that no other bit (another core's) is written.
#include "duet/stm32mp15/rcc.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace duet::stm32mp15 {
namespace {

class RccTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return registers[offset / 4]; }
  std::vector<std::uint32_t> registers = std::vector<std::uint32_t>(0xAB0 / 4);
  Rcc rcc{reinterpret_cast<std::uintptr_t>(registers.data())};
};

TEST_F(RccTest, EachClockIsOneBitInItsSetRegister) {
  rcc.enable(clock::tim7);
  EXPECT_EQ(reg(0xA80), 1U << 5);
  rcc.enable(clock::tim2);
  EXPECT_EQ(reg(0xA80), 1U << 0);  // a store, not a read-modify-write: the set register keeps the others
  rcc.enable(clock::spi5);
  EXPECT_EQ(reg(0xA88), 1U << 10);
  rcc.enable(clock::dmamux);
  EXPECT_EQ(reg(0xA98), 1U << 2);
  rcc.enable(clock::ipcc);
  EXPECT_EQ(reg(0xAA0), 1U << 12);
  rcc.enable(clock::hsem);
  EXPECT_EQ(reg(0xAA0), 1U << 11);
  rcc.enable(clock::gpio(7));  // GPIOH
  EXPECT_EQ(reg(0xAA8), 1U << 7);
}

}  // namespace
}  // namespace duet::stm32mp15
