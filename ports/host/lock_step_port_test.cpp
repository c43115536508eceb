#include "duet/host/lock_step_port.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "duet/rt/executive.hpp"

namespace duet::host {
namespace {

std::vector<std::string> trace;
LockStepPort* active_port = nullptr;

void record(const char* event) { trace.emplace_back(event); }
void base() { record("base"); }
void every_2() {
  record("+2");
  active_port->raise(3);  // an interrupt the slow rate's work causes: more urgent, it preempts
  record("-2");
}
void every_4() { record("4"); }
void interrupt_task() { record("irq"); }
void nothing() {}

constexpr rt::Task tasks[] = {
    {.name = "base", .priority = {2, 0}, .entry = base},
    {.name = "every 2", .period_ticks = 2, .priority = {3, 0}, .entry = every_2},
    {.name = "every 4", .period_ticks = 4, .priority = {4, 0}, .entry = every_4},
    {.name = "irq", .kind = rt::TaskKind::interrupt, .priority = {1, 0}, .entry = interrupt_task},
};
constexpr rt::ModelDescription model{.name = "lock step",
                                     .base_period_ns = 500'000,
                                     .tasks = tasks,
                                     .initialize = nothing,
                                     .terminate = nothing,
                                     .tasking_mode = rt::TaskingMode::multi,
                                     .final_tick = 8};

TEST(LockStepPort, RunsTheModelInVirtualTimeWithTheNvicsOrder) {
  trace.clear();
  LockStepPort port{model};
  active_port = &port;
  rt::Executive<LockStepPort, 4> executive{model, port};
  port.attach(executive);
  ASSERT_EQ(executive.initialize(), rt::TaskTableError::none);
  executive.run();  // idling advances time: runs to the final tick
  executive.terminate();

  EXPECT_EQ(executive.ticks(), 8U);
  EXPECT_EQ(port.now_ns(), 8U * 500'000U);
  EXPECT_EQ(executive.statistics(0).activations, 8U);
  EXPECT_EQ(executive.statistics(1).activations, 4U);
  EXPECT_EQ(executive.statistics(2).activations, 2U);
  EXPECT_EQ(executive.statistics(3).activations, 4U);
  // Tick 0: the base rate, then the triggered rates in rate-monotonic order; the interrupt raised inside rate 2
  // preempts it.
  const std::vector<std::string> first_tick(trace.begin(), trace.begin() + 6);
  EXPECT_EQ(first_tick, (std::vector<std::string>{"base", "+2", "irq", "-2", "4", "base"}));
  EXPECT_EQ(executive.state(), rt::ExecutiveState::terminated);
}

TEST(LockStepPort, TheCallerCanDriveTimeItself) {
  trace.clear();
  LockStepPort port{model};
  active_port = &port;
  rt::Executive<LockStepPort, 4> executive{model, port};
  port.attach(executive);
  ASSERT_EQ(executive.initialize(), rt::TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  port.advance(3);
  port.raise(3);  // a simulated peripheral between ticks
  EXPECT_EQ(executive.ticks(), 3U);
  EXPECT_EQ(executive.statistics(3).activations, 3U);  // two from rate 2's work, one raised here
  executive.end();
  port.advance(5);  // the timer is stopped: time stands still
  EXPECT_EQ(executive.ticks(), 3U);
  EXPECT_EQ(port.now_ns(), 3U * 500'000U);
}

}  // namespace
}  // namespace duet::host
