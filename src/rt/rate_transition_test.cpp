#include "duet/rt/rate_transition.hpp"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace duet::rt {
namespace {

TEST(FastToSlow, TheSlowTaskSeesTheValueOfItsReleaseTickForItsWholePeriod) {
  FastToSlow<int> transition;
  std::vector<int> seen_by_slow;
  constexpr std::uint64_t slow_period = 3;
  for (std::uint64_t tick = 0; tick < 9; ++tick) {
    const bool release = tick % slow_period == 0;
    transition.write(static_cast<int>(tick) * 10, release);  // the fast task, first
    seen_by_slow.push_back(transition.read());               // the slow task, whenever it runs in its period
  }
  EXPECT_EQ(seen_by_slow, (std::vector<int>{0, 0, 0, 30, 30, 30, 60, 60, 60}));
}

TEST(SlowToFast, TheFastTaskSeesTheLastCompletedSlowActivationHeldForAPeriod) {
  SlowToFast<int> transition;
  std::vector<int> seen_by_fast;
  constexpr std::uint64_t slow_period = 2;
  for (std::uint64_t tick = 0; tick < 6; ++tick) {
    const bool release = tick % slow_period == 0;
    seen_by_fast.push_back(transition.read(release));             // the fast task runs first at a release tick
    if (release) transition.write(static_cast<int>(tick) + 100);  // then the slow activation of this period
  }
  // One slow period of delay: the activation released at tick 0 is seen from tick 2 on.
  EXPECT_EQ(seen_by_fast, (std::vector<int>{0, 0, 100, 100, 102, 102}));
}

TEST(AsyncTransfer, TheReaderGetsTheNewestValueOrKeepsTheLastOne) {
  AsyncTransfer<int> transfer;
  EXPECT_EQ(transfer.read(), 0);
  transfer.write(1);
  transfer.write(2);
  EXPECT_EQ(transfer.read(), 2);
  EXPECT_EQ(transfer.read(), 2);  // nothing new: the same value again
  transfer.write(3);
  EXPECT_EQ(transfer.read(), 3);
}

// Every word of a sample holds the same number: a reader that sees two different numbers saw a torn value.
struct Sample {
  std::array<std::uint32_t, 16> words;
};

TEST(AsyncTransfer, AWriterThreadHammeringAReaderThreadNeverTearsAValue) {
  AsyncTransfer<Sample> transfer;
  constexpr std::uint32_t writes = 200'000;
  constexpr std::uint64_t overlapping_reads = 1000;
  std::atomic<std::uint64_t> reads{0};
  std::atomic<std::uint32_t> written{0};  // the last value, once the writer is done
  // The writer goes on until the reader has read a while beside it, however the two threads are scheduled.
  std::thread writer([&] {
    std::uint32_t number = 1;
    for (; number <= writes || reads.load() < overlapping_reads; ++number) {
      Sample sample{};
      sample.words.fill(number);
      transfer.write(sample);
    }
    written = number - 1;
  });
  std::uint32_t torn = 0;
  std::uint32_t went_back = 0;
  std::uint32_t last = 0;
  while (written.load() == 0 || last != written.load()) {
    const Sample& sample = transfer.read();
    for (std::uint32_t word : sample.words) torn += word != sample.words[0] ? 1U : 0U;
    went_back += sample.words[0] < last ? 1U : 0U;
    last = sample.words[0];
    reads.fetch_add(1);
  }
  writer.join();
  EXPECT_EQ(torn, 0U);
  EXPECT_EQ(went_back, 0U);
  EXPECT_GE(last, writes);
  EXPECT_GE(reads.load(), overlapping_reads);
}

}  // namespace
}  // namespace duet::rt
