// The EXTI against a fake register file: the IMU's INT (PE8) routed to line 8 on rising edges, unmasked for the M4,
// stale flags cleared; acknowledging clears both pending flags of that line only.
#include "duet/stm32mp15/exti.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace duet::stm32mp15 {
namespace {

class ExtiTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return registers[offset / 4]; }
  std::vector<std::uint32_t> registers = std::vector<std::uint32_t>(0xC8 / 4);
  Exti exti{reinterpret_cast<std::uintptr_t>(registers.data())};
};

TEST_F(ExtiTest, TheImusInterruptOnPe8) {
  reg(Exti::exticr1 + 8) = 0x0101'0101;  // lines 8-11 on port B
  reg(Exti::ftsr1) = 0xFFFF;
  exti.connect(8, 4, true, false);
  EXPECT_EQ(reg(Exti::exticr1 + 8), 0x0101'0104U);  // EXTICR3's first field: port E
  EXPECT_EQ(reg(Exti::rtsr1), 1U << 8);
  EXPECT_EQ(reg(Exti::ftsr1), 0xFEFFU);
  EXPECT_EQ(reg(Exti::c2imr1), 1U << 8);
  EXPECT_EQ(reg(Exti::rpr1), 1U << 8);  // a stale edge cleared
}

TEST_F(ExtiTest, BothEdgesAndTheirFlags) {
  exti.connect(11, 7, true, true);  // e.g. an echo pin on PH11
  EXPECT_EQ(reg(Exti::rtsr1), 1U << 11);
  EXPECT_EQ(reg(Exti::ftsr1), 1U << 11);
  EXPECT_EQ(reg(Exti::exticr1 + 8), 7U << 24);
  reg(Exti::rpr1) = 1U << 11;
  reg(Exti::fpr1) = 0;
  EXPECT_TRUE(exti.rose(11));
  EXPECT_FALSE(exti.fell(11));
  exti.acknowledge(11);
  EXPECT_EQ(reg(Exti::rpr1), 1U << 11);  // written one: clears line 11's flag alone
  EXPECT_EQ(reg(Exti::fpr1), 1U << 11);
}

}  // namespace
}  // namespace duet::stm32mp15
