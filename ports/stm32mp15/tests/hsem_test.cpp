// The hardware semaphores against a fake register file, where a read of RLRx answers what the chip would: the M4's
// lock when the semaphore was free, Linux's when Linux holds it. A take succeeds on the M4's lock only, gives up
// after a bounded number of reads, counted; a release writes the M4's core number with LOCK clear.
#include "duet/stm32mp15/hsem.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace duet::stm32mp15 {
namespace {

constexpr std::uint32_t linux_lock = Hsem::locked | 1U << 8U;  // COREID 1: a Cortex-A7

class HsemTest : public ::testing::Test {
 protected:
  std::uint32_t& write_lock(unsigned semaphore) { return registers[semaphore]; }
  std::uint32_t& read_lock(unsigned semaphore) { return registers[Hsem::read_lock_offset / 4 + semaphore]; }
  std::array<std::uint32_t, 64> registers{};
  Hsem hsem{reinterpret_cast<std::uintptr_t>(registers.data())};
};

TEST_F(HsemTest, TheBlockAndStsNumbering) {
  EXPECT_EQ(hsem_base, 0x4C00'0000U);
  EXPECT_EQ(semaphore::gpio, 0U);
  EXPECT_EQ(semaphore::exti, 1U);
}

TEST_F(HsemTest, ATakeSucceedsWhenTheReadFindsTheM4sLockAndTheReleaseClearsIt) {
  read_lock(semaphore::exti) = Hsem::locked | Hsem::m4_core;
  write_lock(semaphore::exti) = Hsem::locked | Hsem::m4_core;
  const std::uint32_t failed_before = Hsem::failed_takes();
  EXPECT_TRUE(hsem.take(semaphore::exti));
  hsem.release(semaphore::exti);
  EXPECT_EQ(write_lock(semaphore::exti), 0x200U);  // COREID 2, PROCID 0, LOCK 0
  EXPECT_EQ(write_lock(semaphore::gpio), 0U);      // the other semaphores untouched
  EXPECT_EQ(Hsem::failed_takes(), failed_before);
}

TEST_F(HsemTest, ATakeOfASemaphoreLinuxHoldsGivesUpCounted) {
  read_lock(semaphore::gpio) = linux_lock;
  const std::uint32_t failed_before = Hsem::failed_takes();
  EXPECT_FALSE(hsem.take(semaphore::gpio));
  EXPECT_EQ(Hsem::failed_takes(), failed_before + 1);
  read_lock(semaphore::gpio) = Hsem::locked;  // another process of the M4's core (not the 1-step lock's 0)
  EXPECT_FALSE(hsem.take(semaphore::gpio));
  EXPECT_EQ(Hsem::failed_takes(), failed_before + 2);
}

TEST_F(HsemTest, HoldingRunsTheChangeOnlyWithTheSemaphoreAndReleasesIt) {
  int changes = 0;
  read_lock(semaphore::gpio) = linux_lock;
  EXPECT_FALSE(hsem.holding(semaphore::gpio, [&] { ++changes; }));
  EXPECT_EQ(changes, 0);
  EXPECT_EQ(write_lock(semaphore::gpio), 0U);  // nothing released that was not taken

  read_lock(semaphore::gpio) = Hsem::locked | Hsem::m4_core;
  write_lock(semaphore::gpio) = Hsem::locked | Hsem::m4_core;
  EXPECT_TRUE(hsem.holding(semaphore::gpio, [&] {
    ++changes;
    EXPECT_EQ(write_lock(semaphore::gpio), Hsem::locked | Hsem::m4_core);  // still held during the change
  }));
  EXPECT_EQ(changes, 1);
  EXPECT_EQ(write_lock(semaphore::gpio), Hsem::m4_core);
}

}  // namespace
}  // namespace duet::stm32mp15
