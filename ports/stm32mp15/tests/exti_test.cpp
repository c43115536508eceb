// The EXTI against a fake register file: the IMU's INT (PE8) routed to line 8 on rising edges, unmasked for the M4,
// stale flags cleared, holding the EXTI hardware semaphore and nothing changed while Linux holds it; acknowledging
// clears both pending flags of that line only.
#include "duet/stm32mp15/exti.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace duet::stm32mp15 {
namespace {

class ExtiTest : public ::testing::Test {
 protected:
  ExtiTest() { semaphore_answer() = Hsem::locked | Hsem::m4_core; }  // free: the read takes it for the M4
  std::uint32_t& reg(std::uint32_t offset) { return registers[offset / 4]; }
  std::uint32_t& semaphore_answer() { return semaphores[Hsem::read_lock_offset / 4 + semaphore::exti]; }
  std::uint32_t& semaphore_release() { return semaphores[semaphore::exti]; }
  std::vector<std::uint32_t> registers = std::vector<std::uint32_t>(0xC8 / 4);
  std::array<std::uint32_t, 64> semaphores{};
  Exti exti{reinterpret_cast<std::uintptr_t>(registers.data()),
            Hsem{reinterpret_cast<std::uintptr_t>(semaphores.data())}};
};

TEST_F(ExtiTest, TheImusInterruptOnPe8) {
  reg(Exti::exticr1 + 8) = 0x0101'0101;  // lines 8-11 on port B
  reg(Exti::ftsr1) = 0xFFFF;
  EXPECT_TRUE(exti.connect(8, 4, true, false));
  EXPECT_EQ(semaphore_release(), Hsem::m4_core);    // released after
  EXPECT_EQ(reg(Exti::exticr1 + 8), 0x0101'0104U);  // EXTICR3's first field: port E
  EXPECT_EQ(reg(Exti::rtsr1), 1U << 8);
  EXPECT_EQ(reg(Exti::ftsr1), 0xFEFFU);
  EXPECT_EQ(reg(Exti::c2imr1), 1U << 8);
  EXPECT_EQ(reg(Exti::rpr1), 1U << 8);  // a stale edge cleared
}

TEST_F(ExtiTest, BothEdgesAndTheirFlags) {
  EXPECT_TRUE(exti.connect(11, 7, true, true));  // e.g. an echo pin on PH11
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

TEST_F(ExtiTest, NothingChangesWhileLinuxHoldsTheSemaphore) {
  semaphore_answer() = Hsem::locked | 1U << 8U;  // a Cortex-A7's lock
  EXPECT_FALSE(exti.connect(8, 4, true, false));
  for (const std::uint32_t offset : {Exti::exticr1 + 8, Exti::rtsr1, Exti::rpr1, Exti::c2imr1}) {
    EXPECT_EQ(reg(offset), 0U) << offset;  // not even the M4's own mask: a line half set up stays off
  }
  EXPECT_EQ(semaphore_release(), 0U);
}

}  // namespace
}  // namespace duet::stm32mp15
