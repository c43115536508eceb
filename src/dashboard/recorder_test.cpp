#include "duet/dashboard/recorder.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace duet::dashboard {
namespace {

constexpr double period_s = 0.001;

// Feeds a ramp on signal 1 (value = sample number) with signal 0 its negation, until a capture comes.
std::optional<Capture> feed_ramp(Recorder& recorder, int samples) {
  for (int k = 0; k < samples; ++k) {
    const std::array<double, 2> values{-k * 1.0, k * 1.0};
    if (auto capture = recorder.take(k * period_s, values)) return capture;
  }
  return std::nullopt;
}

TEST(Recorder, CapturesThePreAndPostTriggerTimeAroundARisingCrossing) {
  Recorder recorder;
  ASSERT_TRUE(
      recorder.arm({.signal = 1, .level = 500, .edge = Edge::rising, .pre_s = 0.1, .post_s = 0.2}, 2, period_s).ok());
  EXPECT_EQ(recorder.state(), Recorder::State::armed);
  const auto capture = feed_ramp(recorder, 2000);
  ASSERT_TRUE(capture);
  EXPECT_DOUBLE_EQ(capture->trigger_time_s, 0.5);
  EXPECT_NEAR(capture->time_s.front(), 0.4, 1e-9);
  EXPECT_NEAR(capture->time_s.back(), 0.7, 1e-9);
  ASSERT_EQ(capture->values.size(), 2U);
  EXPECT_EQ(capture->values[1].size(), capture->time_s.size());
  EXPECT_EQ(capture->values[0].front(), -400.0);
  EXPECT_EQ(recorder.state(), Recorder::State::idle);
}

TEST(Recorder, AFallingEdgeIgnoresRisingCrossings) {
  Recorder recorder;
  ASSERT_TRUE(
      recorder.arm({.signal = 0, .level = -10, .edge = Edge::rising, .pre_s = 0, .post_s = 0}, 2, period_s).ok());
  EXPECT_FALSE(feed_ramp(recorder, 100));  // signal 0 falls through -10: no rising crossing
  ASSERT_TRUE(
      recorder.arm({.signal = 0, .level = -10, .edge = Edge::falling, .pre_s = 0, .post_s = 0}, 2, period_s).ok());
  const auto capture = feed_ramp(recorder, 100);
  ASSERT_TRUE(capture);
  EXPECT_DOUBLE_EQ(capture->trigger_time_s, 0.010);
  ASSERT_TRUE(
      recorder.arm({.signal = 0, .level = -10, .edge = Edge::either, .pre_s = 0, .post_s = 0}, 2, period_s).ok());
  EXPECT_TRUE(feed_ramp(recorder, 100));
}

TEST(Recorder, AValueAlreadyPastTheLevelWhenArmedIsNoTrigger) {
  Recorder recorder;
  ASSERT_TRUE(recorder.arm({.signal = 1, .level = 0.5, .edge = Edge::rising}, 2, period_s).ok());
  for (int k = 0; k < 10; ++k) {
    const std::array<double, 2> values{0, 1};
    EXPECT_FALSE(recorder.take(k * period_s, values));
  }
  EXPECT_EQ(recorder.state(), Recorder::State::armed);
}

TEST(Recorder, RefusesSettingsItCannotHonour) {
  Recorder recorder;
  EXPECT_FALSE(recorder.arm({.signal = 2}, 2, period_s).ok());
  EXPECT_FALSE(recorder.arm({.signal = 0, .pre_s = -1}, 2, period_s).ok());
  EXPECT_FALSE(recorder.arm({.signal = 0, .level = NAN}, 2, period_s).ok());
  EXPECT_FALSE(recorder.arm({.signal = 0, .pre_s = 100, .post_s = 150}, 2, period_s).ok());  // 250,000 samples
  EXPECT_EQ(recorder.state(), Recorder::State::idle);
}

TEST(Recorder, CancelDisarms) {
  Recorder recorder;
  ASSERT_TRUE(recorder.arm({.signal = 1, .level = 5}, 2, period_s).ok());
  recorder.cancel();
  EXPECT_FALSE(feed_ramp(recorder, 100));
  EXPECT_EQ(name_of(recorder.state()), "idle");
  EXPECT_EQ(edge_named("either"), Edge::either);
  EXPECT_FALSE(edge_named("sideways"));
}

}  // namespace
}  // namespace duet::dashboard
