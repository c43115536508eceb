#include "duet/rt/executive.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace duet::rt {
namespace {

// The ceiling of every critical section taken, in order.
std::vector<unsigned> sections_taken;

// A port whose clock, pending base tick and idle loop the test controls, and which records what the executive did.
struct FakePort {
  struct CriticalSection {
    explicit CriticalSection(Ceiling ceiling) { sections_taken.push_back(ceiling.priority); }
  };

  [[nodiscard]] std::uint32_t cycles() const { return now; }
  void start_base_timer(std::uint32_t period_ns) { timer_period_ns = period_ns; }
  void stop_base_timer() { timer_period_ns = 0; }
  [[nodiscard]] bool base_tick_pending() const { return tick_pending; }
  void skip_base_tick() {
    tick_pending = false;
    ++skipped_ticks;
  }
  void trigger_rate(std::size_t rate) { triggered_rates.push_back(rate); }
  void idle() const { on_idle(); }
  void task_started(std::size_t task) { trace.push_back("+" + std::to_string(task)); }
  void task_finished(std::size_t task) { trace.push_back("-" + std::to_string(task)); }

  std::uint32_t now = 0;
  std::uint32_t timer_period_ns = 0;
  bool tick_pending = false;
  int skipped_ticks = 0;
  std::vector<std::size_t> triggered_rates;
  std::vector<std::string> trace;
  std::function<void()> on_idle = [] {};
};

// The model's entry points are plain functions, as generated code's are; they act through this fixture state.
struct ModelState {
  FakePort* port = nullptr;
  std::uint32_t base_cost = 0;
  std::uint32_t slow_cost = 0;
  std::uint32_t interrupt_cost = 0;
  std::function<void()> inside_slow_rate = [] {};
  int initialized = 0;
  int terminated = 0;
};
ModelState model_state;

void initialize() { ++model_state.initialized; }
void terminate() { ++model_state.terminated; }
void base_step() { model_state.port->now += model_state.base_cost; }
void slow_step() {
  model_state.port->now += model_state.slow_cost;
  model_state.inside_slow_rate();
}
void interrupt_body() { model_state.port->now += model_state.interrupt_cost; }
void nothing() {}

constexpr Task tasks[] = {
    {.name = "base", .kind = TaskKind::periodic, .period_ticks = 1, .priority = {1, 0}, .entry = base_step},
    {.name = "every 2", .kind = TaskKind::periodic, .period_ticks = 2, .priority = {2, 0}, .entry = slow_step},
    {.name = "every 5", .kind = TaskKind::periodic, .period_ticks = 5, .priority = {3, 0}, .entry = nothing},
    {.name = "uart", .kind = TaskKind::interrupt, .interrupt = 3, .priority = {1, 0}, .entry = interrupt_body},
};

constexpr ModelDescription model_with(TaskingMode mode, OverrunPolicy policy = OverrunPolicy::count_and_skip,
                                      std::uint64_t final_tick = 0, bool wait_for_start = false) {
  return {.name = "test",
          .base_period_ns = 1'000'000,
          .tasks = tasks,
          .initialize = initialize,
          .terminate = terminate,
          .tasking_mode = mode,
          .overrun_policy = policy,
          .final_tick = final_tick,
          .wait_for_start = wait_for_start};
}
static_assert(check(model_with(TaskingMode::single)) == TaskTableError::none);
static_assert(rate_count(model_with(TaskingMode::single)) == 3);

class ExecutiveTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_state = {.port = &port};
    sections_taken.clear();
  }

  FakePort port;
};

TEST_F(ExecutiveTest, SingleTaskingRunsEveryDueRateFastestFirstInTheTimerInterrupt) {
  const ModelDescription model = model_with(TaskingMode::single);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  EXPECT_EQ(port.timer_period_ns, 1'000'000U);
  for (int tick = 0; tick < 10; ++tick) executive.on_base_tick();

  EXPECT_EQ(executive.ticks(), 10U);
  EXPECT_EQ(executive.statistics(0).activations, 10U);
  EXPECT_EQ(executive.statistics(1).activations, 5U);
  EXPECT_EQ(executive.statistics(2).activations, 2U);
  // Tick 0 releases every rate: they run one after another, fastest first, none inside another.
  const std::vector<std::string> first_tick(port.trace.begin(), port.trace.begin() + 6);
  EXPECT_EQ(first_tick, (std::vector<std::string>{"+0", "-0", "+1", "-1", "+2", "-2"}));
  EXPECT_TRUE(port.triggered_rates.empty());
}

TEST_F(ExecutiveTest, ReleaseTicksFollowTheRatesPeriodsAlsoAcrossASkippedTick) {
  const ModelDescription model = model_with(TaskingMode::single);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  for (std::uint64_t tick = 0; tick < 12; ++tick) {
    ASSERT_EQ(executive.ticks(), tick);
    EXPECT_EQ(executive.is_release_tick(1), tick % 2 == 0) << tick;
    EXPECT_EQ(executive.is_release_tick(2), tick % 5 == 0) << tick;
    port.tick_pending = tick == 6;  // tick 7 is skipped
    executive.on_base_tick();
    if (tick == 6) ++tick;
  }
}

TEST_F(ExecutiveTest, MultitaskingTriggersEachSlowerRateAndRunsItFromItsOwnInterrupt) {
  const ModelDescription model = model_with(TaskingMode::multi);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  for (int tick = 0; tick < 10; ++tick) {
    port.triggered_rates.clear();
    executive.on_base_tick();
    for (std::size_t rate : port.triggered_rates) executive.on_rate_interrupt(rate);  // the port's dispatch
  }
  EXPECT_EQ(executive.statistics(0).activations, 10U);
  EXPECT_EQ(executive.statistics(1).activations, 5U);
  EXPECT_EQ(executive.statistics(2).activations, 2U);
  EXPECT_EQ(executive.statistics(1).overruns, 0U);
}

TEST_F(ExecutiveTest, MultitaskingCountsASlowRateThatIsStillRunningAtItsNextRelease) {
  const ModelDescription model = model_with(TaskingMode::multi);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  // Rate 1 is released at ticks 0, 2, 4 but its interrupt only runs after tick 4: two releases find it unfinished.
  for (int tick = 0; tick < 5; ++tick) executive.on_base_tick();
  EXPECT_EQ(port.triggered_rates, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(executive.statistics(1).overruns, 2U);
  executive.on_rate_interrupt(1);
  executive.on_base_tick();
  executive.on_base_tick();  // tick 6 releases rate 1 again
  EXPECT_EQ(port.triggered_rates, (std::vector<std::size_t>{1, 2, 1}));
  EXPECT_EQ(executive.state(), ExecutiveState::running);
}

TEST_F(ExecutiveTest, BaseOverrunIsCountedAndTheLateTickSkipped) {
  const ModelDescription model = model_with(TaskingMode::single);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  executive.on_base_tick();
  port.tick_pending = true;  // the step took longer than the period
  executive.on_base_tick();
  EXPECT_EQ(executive.statistics(0).overruns, 1U);
  EXPECT_EQ(port.skipped_ticks, 1);
  EXPECT_EQ(executive.ticks(), 3U);  // the skipped tick counts as time, not as an activation
  EXPECT_EQ(executive.statistics(0).activations, 2U);
  EXPECT_EQ(executive.state(), ExecutiveState::running);
}

TEST_F(ExecutiveTest, StopPolicyStopsTheModelOnOverrunAndTerminateRuns) {
  const ModelDescription model = model_with(TaskingMode::single, OverrunPolicy::stop);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  int idles = 0;
  port.on_idle = [&] {
    port.tick_pending = ++idles == 3;
    executive.on_base_tick();
  };
  executive.run();
  executive.terminate();
  EXPECT_EQ(executive.stop_reason(), StopReason::overrun);
  EXPECT_EQ(executive.statistics(0).overruns, 1U);
  EXPECT_EQ(executive.statistics(0).activations, 3U);
  EXPECT_EQ(executive.state(), ExecutiveState::terminated);
  EXPECT_EQ(model_state.terminated, 1);
  EXPECT_EQ(port.timer_period_ns, 0U);  // the timer is stopped again
}

TEST_F(ExecutiveTest, WaitsForAStartRequestAndStopsAtTheFinalTick) {
  const ModelDescription model = model_with(TaskingMode::single, OverrunPolicy::stop, 7, true);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  EXPECT_EQ(model_state.initialized, 1);
  EXPECT_EQ(executive.state(), ExecutiveState::waiting_for_start);
  int idles_before_start = 0;
  port.on_idle = [&] {
    if (executive.state() == ExecutiveState::waiting_for_start) {
      if (++idles_before_start == 4) executive.start();  // external mode says start
      return;
    }
    executive.on_base_tick();
  };
  executive.run();
  executive.terminate();
  EXPECT_EQ(idles_before_start, 4);
  EXPECT_EQ(executive.ticks(), 7U);
  EXPECT_EQ(executive.stop_reason(), StopReason::final_tick);
  EXPECT_EQ(model_state.terminated, 1);
}

TEST_F(ExecutiveTest, AStopBeforeStartSkipsRunningButStillTerminates) {
  const ModelDescription model = model_with(TaskingMode::single, OverrunPolicy::stop, 0, true);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  port.on_idle = [&] { executive.request_stop(StopReason::external); };
  executive.run();
  executive.terminate();
  EXPECT_EQ(executive.ticks(), 0U);
  EXPECT_EQ(executive.stop_reason(), StopReason::external);
  EXPECT_EQ(model_state.terminated, 1);
}

TEST_F(ExecutiveTest, ExecutionTimesExcludeTheTasksThatPreemptedThem) {
  const ModelDescription model = model_with(TaskingMode::multi);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  model_state.base_cost = 100;
  model_state.slow_cost = 700;
  model_state.interrupt_cost = 30;
  // The slow rate is preempted by the next base tick and by an interrupt task in the middle of its work.
  bool preempted = false;
  model_state.inside_slow_rate = [&] {
    if (preempted) return;
    preempted = true;
    executive.on_base_tick();
    executive.on_interrupt_task(3);
    port.now += 50;
  };
  port.now = 1000;
  executive.on_base_tick();
  executive.on_rate_interrupt(1);

  EXPECT_EQ(executive.statistics(0).max_cycles, 100U);
  EXPECT_EQ(executive.statistics(3).max_cycles, 30U);
  EXPECT_EQ(executive.statistics(1).max_cycles, 750U);  // 700 before, 50 after; not the 130 of the others
  EXPECT_EQ(executive.statistics(1).mean_cycles(), 750U);
  EXPECT_EQ(executive.load().busy_cycles, 100U + 100U + 30U + 750U);
}

TEST_F(ExecutiveTest, LoadIsBusyTimeOverElapsedTime) {
  const ModelDescription model = model_with(TaskingMode::single);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  model_state.base_cost = 250;
  for (int tick = 0; tick < 5; ++tick) {
    port.now = static_cast<std::uint32_t>(tick) * 1000U;
    executive.on_base_tick();
  }
  // Five steps of 250 cycles; four full periods of 1000 cycles elapsed between the first and the last tick.
  EXPECT_EQ(executive.load().elapsed_cycles, 4000U);
  EXPECT_EQ(executive.load().busy_cycles, 1250U);
  EXPECT_EQ((CoreLoad{.busy_cycles = 1000, .elapsed_cycles = 4000}.busy_ppm()), 250000U);
}

TEST_F(ExecutiveTest, ElapsedTimeCountsOnAcrossTheCycleCountersWraps) {
  const ModelDescription model = model_with(TaskingMode::single);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  port.now = 0xFFFF'0000U;
  ASSERT_TRUE(executive.begin());
  // Ticks of 2^31 cycles: the 32-bit counter wraps every other tick.
  for (std::uint32_t tick = 1; tick <= 5; ++tick) {
    port.now = 0xFFFF'0000U + tick * 0x8000'0000U;
    executive.on_base_tick();
  }
  EXPECT_EQ(executive.load().elapsed_cycles, 5ULL * 0x8000'0000U);
}

TEST(TaskTable, RejectsTablesTheExecutiveCannotRun) {
  ModelDescription model = model_with(TaskingMode::single);
  EXPECT_EQ(check(model), TaskTableError::none);

  constexpr Task no_base[] = {{.name = "slow", .period_ticks = 2, .entry = nothing}};
  model.tasks = no_base;
  EXPECT_EQ(check(model), TaskTableError::no_base_rate);

  constexpr Task slow_before_fast[] = {{.name = "base", .entry = nothing},
                                       {.name = "10", .period_ticks = 10, .entry = nothing},
                                       {.name = "5", .period_ticks = 5, .entry = nothing}};
  model.tasks = slow_before_fast;
  EXPECT_EQ(check(model), TaskTableError::rates_not_fastest_first);

  constexpr Task rate_after_interrupt[] = {{.name = "base", .entry = nothing},
                                           {.name = "irq", .kind = TaskKind::interrupt, .entry = nothing},
                                           {.name = "5", .period_ticks = 5, .entry = nothing}};
  model.tasks = rate_after_interrupt;
  EXPECT_EQ(check(model), TaskTableError::rates_not_fastest_first);

  model.tasking_mode = TaskingMode::multi;
  constexpr Task slow_as_urgent_as_fast[] = {{.name = "base", .priority = {2, 0}, .entry = nothing},
                                             {.name = "5", .period_ticks = 5, .priority = {2, 0}, .entry = nothing}};
  model.tasks = slow_as_urgent_as_fast;
  EXPECT_EQ(check(model), TaskTableError::rates_not_rate_monotonic);
  model.tasking_mode = TaskingMode::single;
  EXPECT_EQ(check(model), TaskTableError::none);

  constexpr Task sub_priority_without_bits[] = {{.name = "base", .priority = {0, 1}, .entry = nothing}};
  model.tasks = sub_priority_without_bits;
  EXPECT_EQ(check(model), TaskTableError::priority_out_of_range);
  model.sub_priority_bits = 1;
  EXPECT_EQ(check(model), TaskTableError::none);
  constexpr Task group_beyond_three_bits[] = {{.name = "base", .priority = {8, 0}, .entry = nothing}};
  model.tasks = group_beyond_three_bits;
  EXPECT_EQ(check(model), TaskTableError::priority_out_of_range);
  model.sub_priority_bits = 0;

  constexpr Task missing_entry[] = {{.name = "base"}};
  model.tasks = missing_entry;
  EXPECT_EQ(check(model), TaskTableError::missing_entry);

  model.tasks = {};
  EXPECT_EQ(check(model), TaskTableError::no_tasks);
}

TEST(TaskTable, TheExecutiveRefusesMoreTasksThanItWasSizedFor) {
  FakePort port;
  model_state = {.port = &port};
  const ModelDescription model = model_with(TaskingMode::single);
  Executive<FakePort, 3> executive{model, port};
  EXPECT_EQ(executive.initialize(), TaskTableError::too_many_tasks);
  EXPECT_EQ(model_state.initialized, 0);
  EXPECT_FALSE(executive.begin());
}

// The tasks' groups are 1, 2, 3 and 1: what they all share has ceiling 1, what "every 2" and "every 5" share 2.
constexpr std::size_t slow_rates[] = {1, 2};
static_assert(tasks_ceiling(model_with(TaskingMode::single)) == Ceiling{1});
static_assert(ceiling(model_with(TaskingMode::single), slow_rates) == Ceiling{2});

TEST_F(ExecutiveTest, OnlyTasksBelowTheCeilingOfTheExecutivesDataTakeASectionAtThatCeiling) {
  const ModelDescription model = model_with(TaskingMode::multi);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  ASSERT_TRUE(executive.begin());
  EXPECT_EQ(executive.tasks_ceiling(), Ceiling{1});
  executive.on_base_tick();
  executive.on_interrupt_task(3);
  EXPECT_TRUE(sections_taken.empty()) << "the base rate and the interrupt task are at the ceiling";
  executive.on_rate_interrupt(1);
  EXPECT_EQ(sections_taken, (std::vector<unsigned>{1})) << "one to end the timing; beginning it reads one word";
}

TEST_F(ExecutiveTest, MeasuresTheLongestSectionAtEachCeiling) {
  const ModelDescription model = model_with(TaskingMode::multi);
  Executive<FakePort, 4> executive{model, port};
  ASSERT_EQ(executive.initialize(), TaskTableError::none);
  for (const std::uint32_t length : {7U, 12U, 3U}) {
    const auto section = executive.section(Ceiling{2});
    port.now += length;
  }
  EXPECT_EQ(sections_taken, (std::vector<unsigned>{2, 2, 2}));
  EXPECT_EQ(executive.longest_section(Ceiling{2}), 12U);
  EXPECT_EQ(executive.longest_section(Ceiling{1}), 0U);
}

}  // namespace
}  // namespace duet::rt
