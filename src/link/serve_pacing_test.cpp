// serve() keeping real time itself (ServeOptions::paced), for firmware that cannot: a paced session of N ticks
// takes N periods of wall time whatever the firmware's pace, an unpaced one as long as the firmware takes, and a
// TICK that comes after its time counts as late.
#include <gtest/gtest.h>

#include <chrono>
#include <optional>
#include <thread>

#include "duet/link/remote_plant.hpp"
#include "duet/link/serve.hpp"
#include "duet/plant/plant.hpp"

namespace duet::link {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

struct Session {
  Result<ServeSummary> summary = Failure{"not served"};
  Clock::duration took{};
};

// `ticks` TICKs at `period_ns` from a lock-step firmware (it never waits by itself), against a plant served with
// `options`, `pause` before each TICK but the first.
Session run_session(const ServeOptions& options, int ticks, std::uint32_t period_ns, Clock::duration pause = {}) {
  auto pair = socket_pair(2s);
  EXPECT_TRUE(pair.ok()) << (pair.ok() ? "" : pair.error());
  plant::Loopback loopback;
  std::optional<Result<ServeSummary>> served;
  std::thread plant_side{[&] { served.emplace(serve(loopback, *pair.value().second, options)); }};
  const Clock::time_point start = Clock::now();
  {
    auto connected = RemotePlant::connect(std::move(pair.value().first), {LinkMode::lock_step, period_ns});
    EXPECT_TRUE(connected.ok()) << (connected.ok() ? "" : connected.error());
    for (int tick = 0; connected.ok() && tick < ticks; ++tick) {
      if (tick > 0) std::this_thread::sleep_for(pause);
      connected.value()->advance(tick_time_s(static_cast<std::uint64_t>(tick), period_ns), {});
    }
    EXPECT_TRUE(connected.ok() && connected.value()->ok());
  }  // BYE
  plant_side.join();
  return {*served, Clock::now() - start};
}

TEST(ServePacing, APacedSessionTakesItsTicksInWallTime) {
  const Session paced = run_session({.paced = true}, 51, 4'000'000);  // 50 periods after the first tick
  ASSERT_TRUE(paced.summary.ok()) << paced.summary.error();
  EXPECT_EQ(paced.summary.value().ticks, 51U);
  EXPECT_EQ(paced.summary.value().last_tick_s, 50 * 0.004);
  EXPECT_GE(paced.took, 200ms);
  EXPECT_LT(paced.took, 2s);  // generous: a loaded machine under the sanitizers
}

TEST(ServePacing, AnUnpacedSessionDoesNotWait) {
  const Session unpaced = run_session({}, 51, 4'000'000);
  ASSERT_TRUE(unpaced.summary.ok()) << unpaced.summary.error();
  EXPECT_EQ(unpaced.summary.value().ticks, 51U);
  EXPECT_LT(unpaced.took, 150ms);                                    // the 200 ms the ticks stand for, not waited
  EXPECT_EQ(unpaced.summary.value().pacing.first_second.ticks, 0U);  // nothing paced, nothing counted
}

TEST(ServePacing, ATickThatComesAfterItsTimeIsLate) {
  // 1 ms ticks with 30 ms between them: every TICK after the first is late by some 29 ms more than the one before.
  const Session late = run_session({.paced = true}, 4, 1'000'000, 30ms);
  ASSERT_TRUE(late.summary.ok()) << late.summary.error();
  EXPECT_EQ(late.summary.value().pacing.first_second.ticks, 4U);
  EXPECT_EQ(late.summary.value().pacing.first_second.late, 3U);
  EXPECT_GE(late.summary.value().pacing.first_second.worst, 80ms);
}

}  // namespace
}  // namespace duet::link
