// The simulator against the analysis: simulated responses never exceed the analysed ones, and the critical instant
// reaches them.
#include "duet/sched/simulator.hpp"

#include <gtest/gtest.h>

#include <random>

#include "duet/sched/priority_assignment.hpp"
#include "duet/sched/response_time.hpp"
#include "thesis_task_set.hpp"

namespace duet::sched {
namespace {

TEST(Simulator, TheCriticalInstantReachesTheTextbookResponses) {
  const TaskSet set = in_order(tasks_of({{3, 7}, {3, 12}, {5, 20}}));
  const std::vector<double> largest = largest_responses(set, simulate(set, critical_instant(set, 84)));
  EXPECT_DOUBLE_EQ(largest[0], 3);
  EXPECT_DOUBLE_EQ(largest[1], 6);
  EXPECT_DOUBLE_EQ(largest[2], 20);
}

TEST(Simulator, TheCriticalInstantReachesTheResponsesAtUtilizationOne) {
  // Issue #23's harmonic set (U = 1): the lowest task finishes exactly at its deadline, two hyperperiods running.
  const TaskSet set = in_order(tasks_of({{5, 20}, {10, 40}, {40, 80}}));
  const Analysis analysis = analyse(set).value();
  const std::vector<double> largest = largest_responses(set, simulate(set, critical_instant(set, 160)));
  for (std::size_t task = 0; task < set.tasks.size(); ++task) {
    EXPECT_DOUBLE_EQ(largest[task], analysis.tasks[task].response) << set.tasks[task].name;
  }
  EXPECT_DOUBLE_EQ(largest[2], 80);
}

TEST(Simulator, ALaterJobOfTheBusyPeriodIsTheWorst) {
  TaskSet set = in_order(tasks_of({{26, 70}, {62, 100}}));
  set.tasks[1].deadline = 120;
  const auto jobs = simulate(set, critical_instant(set, 700));
  EXPECT_DOUBLE_EQ(largest_responses(set, jobs)[1], analyse(set).value().tasks[1].response);  // 118, job 4
}

TEST(Simulator, JitterAndOverheadsAreReachedToo) {
  TaskSet set = in_order(tasks_of({{2, 10}, {4, 20}}));
  set.tasks[0].jitter = 5;
  set.core.entry_overhead = 0.25;
  set.core.exit_overhead = 0.25;
  const Analysis analysis = analyse(set).value();
  const std::vector<double> largest = largest_responses(set, simulate(set, critical_instant(set, 100)));
  EXPECT_DOUBLE_EQ(largest[0], analysis.tasks[0].response);
  EXPECT_DOUBLE_EQ(largest[1], analysis.tasks[1].response);
}

TEST(Simulator, AStartedHandlerOfTheSameGroupBlocks) {
  TaskSet set = tasks_of({{2, 10}, {4, 10}});
  set.tasks[0].priority = NvicPriority{0, 0};
  set.tasks[1].priority = NvicPriority{0, 1};
  // t1 starts a hair before t0 arrives: t0 waits for all of it.
  const auto jobs = simulate(set, critical_instant(set, 10, {0.0, -1e-6}));
  EXPECT_NEAR(largest_responses(set, jobs)[0], analyse(set).value().tasks[0].response, 1e-5);
}

TEST(Simulator, TheThesisRobotUnderDeadlineMonotonicLevels) {
  const TaskSet set = with_priorities(thesis_robot_tasks(), deadline_monotonic(thesis_robot_tasks()));
  const Analysis analysis = analyse(set).value();
  const std::vector<double> synchronous = largest_responses(set, simulate(set, critical_instant(set, 200000)));
  for (std::size_t task = 0; task < set.tasks.size(); ++task) {
    EXPECT_LE(synchronous[task], analysis.tasks[task].response + 1e-9) << set.tasks[task].name;
  }
  // Without blocking the synchronous release is the worst case: the analysis is reached exactly.
  EXPECT_NEAR(synchronous[4], analysis.tasks[4].response, 1e-9);
  EXPECT_NEAR(synchronous[0], analysis.tasks[0].response, 1e-9);
  EXPECT_NEAR(synchronous[6], analysis.tasks[6].response, 1e-9);  // 6 waits for 5, which the NVIC takes first
}

TEST(Simulator, RandomPhasingsNeverExceedTheAnalysis) {
  std::mt19937 random{20261122};  // fixed: the same scenarios every run
  TaskSet set = with_priorities(thesis_robot_tasks(), deadline_monotonic(thesis_robot_tasks()));
  for (Task& task : set.tasks) task.jitter = 2.0;
  set.core.masked_section = 0;
  const Analysis analysis = analyse(set).value();
  for (int scenario = 0; scenario < 20; ++scenario) {
    std::vector<Release> releases;
    for (std::size_t task = 0; task < set.tasks.size(); ++task) {
      const Task& t = set.tasks[task];
      std::uniform_real_distribution<double> phase{0, t.period};
      std::uniform_real_distribution<double> delay{0, t.jitter};
      for (double arrival = phase(random); arrival < 50000; arrival += t.period) {
        releases.push_back({task, arrival, arrival + delay(random)});
      }
    }
    const std::vector<double> largest = largest_responses(set, simulate(set, releases));
    for (std::size_t task = 0; task < set.tasks.size(); ++task) {
      ASSERT_LE(largest[task], analysis.tasks[task].response + 1e-9) << "scenario " << scenario << ", task " << task;
    }
  }
}

}  // namespace
}  // namespace duet::sched
