// TIM7 as the executive's base rate, against a fake register file: prescaler and reload for the period, the
// update event that loads them without a tick, the interrupt on, and periods it cannot make refused.
#include "duet/stm32mp15/basic_timer.hpp"

#include <gtest/gtest.h>

#include <array>

namespace duet::stm32mp15 {
namespace {

class BasicTimerTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return registers[offset / 4]; }
  std::array<std::uint32_t, 16> registers{};
  BasicTimer timer{reinterpret_cast<std::uintptr_t>(registers.data())};
};

TEST_F(BasicTimerTest, OneMillisecondFromTheMcuClock) {
  reg(BasicTimer::sr) = BasicTimer::update_flag;
  ASSERT_TRUE(timer.start(1'000'000, 209'000'000));  // 209,000 counts: prescaler 3 (/4), reload 52,249
  EXPECT_EQ(reg(BasicTimer::psc), 3U);
  EXPECT_EQ(reg(BasicTimer::arr), 52'249U);
  EXPECT_EQ(reg(BasicTimer::egr), BasicTimer::update_generation);
  EXPECT_EQ(reg(BasicTimer::sr), 0U);  // the update event's flag is no tick
  EXPECT_EQ(reg(BasicTimer::dier), BasicTimer::update_interrupt);
  EXPECT_EQ(reg(BasicTimer::cr1), BasicTimer::counter_enable | BasicTimer::preload);
}

TEST_F(BasicTimerTest, ShortPeriodsNeedNoPrescaler) {
  ASSERT_TRUE(timer.start(10'000, 209'000'000));  // 10 us: 2,090 counts
  EXPECT_EQ(reg(BasicTimer::psc), 0U);
  EXPECT_EQ(reg(BasicTimer::arr), 2'089U);
}

TEST_F(BasicTimerTest, RefusesWhatItCannotCount) {
  registers.fill(0xAAAA'AAAA);
  EXPECT_FALSE(timer.start(5, 209'000'000));                // one count
  EXPECT_FALSE(timer.start(100'000'000'000, 209'000'000));  // 100 s: beyond 16 + 16 bits
  EXPECT_EQ(reg(BasicTimer::cr1), 0xAAAA'AAAAU);            // nothing touched
}

TEST_F(BasicTimerTest, AcknowledgeClearsOnlyTheUpdateFlag) {
  timer.acknowledge();
  EXPECT_EQ(reg(BasicTimer::sr), ~BasicTimer::update_flag);  // rc_w0: the ones leave the other flags alone
}

}  // namespace
}  // namespace duet::stm32mp15
