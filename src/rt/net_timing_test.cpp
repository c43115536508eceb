#include "duet/rt/net_timing.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace duet::rt {
namespace {

TEST(NetTiming, NestedThreeDeepEachTaskLosesExactlyWhatPreemptedIt) {
  NetTiming timing;
  const NetTiming::Start a = timing.begin(100);
  const NetTiming::Start b = timing.begin(110);  // b preempts a
  const NetTiming::Start c = timing.begin(115);  // c preempts b
  EXPECT_EQ(timing.end(c, 120), 5U);
  EXPECT_EQ(timing.end(b, 130), 20U - 5U);
  const NetTiming::Start d = timing.begin(140);  // another preempts a after b is done
  EXPECT_EQ(timing.end(d, 147), 7U);
  EXPECT_EQ(timing.end(a, 150), 50U - 20U - 7U);
  EXPECT_EQ(timing.busy_cycles(), 50U) << "every cycle once";
}

TEST(NetTiming, TheCycleCounterMayWrapInsideATaskAndTheBusyTotalBeyond32Bits) {
  NetTiming timing;
  for (int task = 0; task < 3; ++task) {
    const NetTiming::Start long_task = timing.begin(0);
    EXPECT_EQ(timing.end(long_task, 0xF000'0000U), 0xF000'0000U);
  }
  const NetTiming::Start a = timing.begin(0xFFFF'FFF0U);
  const NetTiming::Start b = timing.begin(0xFFFF'FFF8U);
  EXPECT_EQ(timing.end(b, 0x0000'0004U), 12U);
  EXPECT_EQ(timing.end(a, 0x0000'0010U), 32U - 12U);
  EXPECT_EQ(timing.busy_cycles(), 3ULL * 0xF000'0000U + 32U);
}

}  // namespace
}  // namespace duet::rt
