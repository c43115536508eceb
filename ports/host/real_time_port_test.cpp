#include "duet/host/real_time_port.hpp"

#include <gtest/gtest.h>

#include <atomic>

#include "duet/rt/executive.hpp"

namespace duet::host {
namespace {

std::atomic<int> terminations{0};
void nothing() {}
void terminate() { ++terminations; }

constexpr rt::Task tasks[] = {
    {.name = "base", .priority = {1, 0}, .entry = nothing},
    {.name = "every 5", .period_ticks = 5, .priority = {2, 0}, .entry = nothing},
    {.name = "external", .kind = rt::TaskKind::interrupt, .priority = {0, 0}, .entry = nothing},
};
constexpr rt::ModelDescription model{.name = "real time",
                                     .base_period_ns = 1'000'000,
                                     .tasks = tasks,
                                     .initialize = nothing,
                                     .terminate = terminate,
                                     .tasking_mode = rt::TaskingMode::multi,
                                     .final_tick = 20};

// Wall-clock time varies from run to run; what is asserted does not: the absolute deadlines mean the run cannot be
// shorter than its ticks, and every tick is either run or counted as an overrun.
TEST(RealTimePort, RunsTheModelAtAbsoluteDeadlinesUntilTheFinalTick) {
  RealTimePort port{model};
  rt::Executive<RealTimePort, 3> executive{model, port};
  port.attach(executive);
  ASSERT_EQ(executive.initialize(), rt::TaskTableError::none);
  const std::uint64_t start = RealTimePort::monotonic_ns();
  executive.run();
  const std::uint64_t elapsed = RealTimePort::monotonic_ns() - start;
  port.raise(2);  // after the stop: the executive ignores it
  executive.terminate();

  EXPECT_EQ(executive.ticks(), 20U);
  EXPECT_EQ(executive.statistics(0).activations + executive.statistics(0).overruns, 20U);
  EXPECT_GE(elapsed, 20U * 1'000'000U);
  EXPECT_EQ(executive.statistics(2).activations, 0U);
  EXPECT_EQ(terminations, 1);
  EXPECT_EQ(executive.stop_reason(), rt::StopReason::final_tick);
}

}  // namespace
}  // namespace duet::host
