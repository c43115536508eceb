#include "duet/blocks/sources.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace duet::blocks {
namespace {

static_assert(std::is_aggregate_v<StepCounter> && sizeof(StepCounter) == sizeof(std::uint32_t));
static_assert(step(2U, 3U, 1.0, 5.0) == 1.0 && step(3U, 3U, 1.0, 5.0) == 5.0);
static_assert(pulse(5U, 4U, 2U, 1U, 7) == 7);

TEST(BlocksStep, InitialBeforeTheStepAndFinalFromItOn) {
  std::vector<float> outputs;
  for (std::uint32_t k = 0; k < 5; ++k) outputs.push_back(step(k, 2U, -1.5F, 2.5F));
  EXPECT_EQ(outputs, (std::vector<float>{-1.5F, -1.5F, 2.5F, 2.5F, 2.5F}));
  EXPECT_EQ(step<std::int16_t>(0U, 0U, 1, 2), 2);  // a step at 0 is final from the start
  EXPECT_EQ(
      step<std::uint8_t>(std::numeric_limits<std::uint32_t>::max(), std::numeric_limits<std::uint32_t>::max(), 1, 2),
      2);
}

TEST(BlocksPulse, StartsAtTheDelayLastsTheWidthAndRepeats) {
  // period 4, width 2, delay 3: k = 0..2 before the delay; then k - 3 = 0, 1 on, 2, 3 off, 4, 5 on, 6 off.
  std::vector<int> outputs;
  for (std::uint32_t k = 0; k < 10; ++k) outputs.push_back(pulse(k, 4U, 2U, 3U, 5));
  EXPECT_EQ(outputs, (std::vector<int>{0, 0, 0, 5, 5, 0, 0, 5, 5, 0}));
}

TEST(BlocksPulse, SquareWaveWithoutDelay) {
  std::vector<double> outputs;
  for (std::uint32_t k = 0; k < 7; ++k) outputs.push_back(pulse(k, 2U, 1U, 0U, -0.5));
  EXPECT_EQ(outputs, (std::vector<double>{-0.5, 0.0, -0.5, 0.0, -0.5, 0.0, -0.5}));
}

TEST(BlocksPulse, EdgeCases) {
  EXPECT_EQ(pulse(7U, 0U, 1U, 0U, 1.0F), 0.0F);  // period 0
  EXPECT_EQ(pulse(7U, 3U, 0U, 0U, 1.0F), 0.0F);  // width 0
  EXPECT_EQ(pulse(7U, 3U, 3U, 0U, 1.0F), 1.0F);  // width = period: always on
  EXPECT_EQ(pulse(7U, 3U, 9U, 2U, 1.0F), 1.0F);  // width > period
  EXPECT_EQ(pulse(1U, 3U, 9U, 2U, 1.0F), 0.0F);  // still before the delay
  constexpr std::uint32_t last = std::numeric_limits<std::uint32_t>::max();
  // (2^32 - 1) - 1 = 4294967294 = 2 * 2147483647: the start of a period.
  EXPECT_EQ(pulse(last, 2147483647U, 1U, 1U, 3), 3);
}

TEST(BlocksStepCounter, CountsAndStopsAtTheMaximum) {
  StepCounter counter{0};
  std::vector<std::uint32_t> outputs;
  for (int i = 0; i < 3; ++i) {
    outputs.push_back(counter.output());
    counter.update();
  }
  EXPECT_EQ(outputs, (std::vector<std::uint32_t>{0, 1, 2}));
  StepCounter almost{std::numeric_limits<std::uint32_t>::max() - 1U};
  almost.update();
  EXPECT_EQ(almost.output(), std::numeric_limits<std::uint32_t>::max());
  almost.update();
  EXPECT_EQ(almost.output(), std::numeric_limits<std::uint32_t>::max());
}

}  // namespace
}  // namespace duet::blocks
