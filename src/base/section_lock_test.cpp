#include "duet/base/section_lock.hpp"

#include <gtest/gtest.h>

namespace duet {
namespace {

int depth = 0;
std::uint32_t restored = 0;
std::uint32_t enter() { return static_cast<std::uint32_t>(++depth) * 10U; }
void leave(std::uint32_t saved) {
  restored = saved;
  --depth;
}

TEST(SectionLock, CallsTheProgramsFunctionsAndHandsBackWhatLockReturned) {
  const SectionLock lock{enter, leave};
  const std::uint32_t saved = lock.lock();
  EXPECT_EQ(depth, 1);
  lock.unlock(saved);
  EXPECT_EQ(depth, 0);
  EXPECT_EQ(restored, 10U);
}

TEST(SectionLock, WithoutFunctionsIsNoLock) {
  const SectionLock none{};
  restored = 99;
  EXPECT_EQ(none.lock(), 0U);
  none.unlock(5);
  EXPECT_EQ(restored, 99U);
}

}  // namespace
}  // namespace duet
