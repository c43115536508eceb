// The analyses against the thesis' figures, the textbook example and hand-computed cases.
#include <gtest/gtest.h>

#include <compare>
#include <cstdint>

#include "duet/sched/priority_assignment.hpp"
#include "duet/sched/response_time.hpp"
#include "duet/sched/utilization.hpp"
#include "natural.hpp"
#include "thesis_task_set.hpp"

namespace duet::sched {
namespace {

TEST(Utilization, Table2Point1) {
  const TaskSet set = tasks_of({{0.25, 1}, {0.25, 2}, {0.05, 2.2}, {0.6, 4}, {0.05, 6}, {1.2, 7}});
  const Utilization u = utilization(set);
  EXPECT_NEAR(u.by_period, 0.7275, 1e-4);  // the thesis prints ~0.713, an arithmetic slip
  EXPECT_NEAR(u.liu_layland_bound, 0.7348, 1e-4);
  EXPECT_TRUE(u.passes_liu_layland());
}

TEST(Utilization, Table4Point9) {
  const Utilization u = utilization(thesis_robot_tasks());
  EXPECT_NEAR(u.by_period, 0.186, 5e-4);
  EXPECT_NEAR(u.by_deadline, 0.686, 5e-4);
  EXPECT_NEAR(u.liu_layland_bound, 0.712, 5e-4);
  EXPECT_TRUE(u.passes_deadline_check());
}

TEST(Utilization, CountsTheCoresOverheads) {
  TaskSet set = tasks_of({{1, 10}, {2, 20}});
  set.core.entry_overhead = 0.5;
  set.core.exit_overhead = 0.5;
  EXPECT_DOUBLE_EQ(utilization(set).by_period, 2.0 / 10 + 3.0 / 20);
}

TEST(Utilization, LiuLaylandBoundsAndTheHyperbolicTest) {
  EXPECT_DOUBLE_EQ(liu_layland_bound(1), 1.0);
  EXPECT_NEAR(liu_layland_bound(2), 0.8284, 1e-4);
  EXPECT_NEAR(liu_layland_bound(5), 0.7435, 1e-4);
  // (0.5, 0.3): U = 0.8 <= 0.8284 and the product 1.95 <= 2. (0.6, 0.3): U = 0.9 fails L&L, the product 2.08 fails.
  EXPECT_TRUE(utilization(tasks_of({{5, 10}, {3, 10}})).passes_hyperbolic());
  EXPECT_FALSE(utilization(tasks_of({{6, 10}, {3, 10}})).passes_hyperbolic());
  // (0.7, 0.15): U = 0.85 fails Liu & Layland, but 1.7 * 1.15 = 1.955 passes the hyperbolic bound.
  const Utilization u = utilization(tasks_of({{7, 10}, {3, 20}}));
  EXPECT_FALSE(u.passes_liu_layland());
  EXPECT_TRUE(u.passes_hyperbolic());
}

TEST(ResponseTime, TheTextbookExample) {
  const Analysis analysis = analyse(in_order(tasks_of({{3, 7}, {3, 12}, {5, 20}}))).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 3);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 6);
  EXPECT_DOUBLE_EQ(analysis.tasks[2].response, 20);
  EXPECT_TRUE(analysis.schedulable());
  EXPECT_GT(utilization(tasks_of({{3, 7}, {3, 12}, {5, 20}})).by_period, liu_layland_bound(3));
}

TEST(ResponseTime, JitterOfAMoreUrgentTaskAddsInterference) {
  // By hand: t0 (C 2, T 10, J 5) can arrive at 0 and again at 5; t1 (C 4, T 20): w = 4 + 2 ceil((w + 5) / 10):
  // w = 6 -> 4 + 2*2 = 8 -> 4 + 2*2 = 8: R1 = 8. t0 itself: R0 = C + J = 7.
  TaskSet set = in_order(tasks_of({{2, 10}, {4, 20}}));
  set.tasks[0].jitter = 5;
  const Analysis analysis = analyse(set).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 7);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 8);
}

TEST(ResponseTime, MaskedSectionsAndOverheadsCount) {
  // Entry 0.5 + exit 0.5 make C 3 and 4; a masked section of 2 blocks both: R0 = 2 + 3 = 5, R1 = 2 + 4 + 3 = 9.
  TaskSet set = in_order(tasks_of({{2, 10}, {3, 20}}));
  set.core.entry_overhead = 0.5;
  set.core.exit_overhead = 0.5;
  set.core.masked_section = 2;
  const Analysis analysis = analyse(set).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].blocking, 2);
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 5);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 9);
}

TEST(ResponseTime, ASectionAtACeilingBlocksOnlyTheTasksAtOrBelowIt) {
  // Groups 0, 1, 2; a section of 3 at ceiling 1 and one of 1 at ceiling 2: t0 is above both (B 0, R 1), t1 is
  // blocked by the longer (B 3, R 3 + 1 + 1 = 5), t2 by either, the longer (B 3, R 3 + 1 + 1 + 1 = 6).
  TaskSet set = in_order(tasks_of({{1, 20}, {1, 20}, {1, 20}}));
  set.core.sections = {{1, 3}, {2, 1}};
  const Analysis analysis = analyse(set).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].blocking, 0);
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 1);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].blocking, 3);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 5);
  EXPECT_DOUBLE_EQ(analysis.tasks[2].blocking, 3);
  EXPECT_DOUBLE_EQ(analysis.tasks[2].response, 6);
}

TEST(ResponseTime, ArbitraryDeadlinesLookAtEveryJobOfTheBusyPeriod) {
  // t0 (C 26, T 70), t1 (C 62, T 100, D 120), the classic case where a later job is the worst (Lehoczky 1990 style):
  // by hand, the level-2 busy period holds 7 jobs of t1; job q finishes at F(q) with
  // F(0) = 114, F(1) = 202, F(2) = 316, F(3) = 404, F(4) = 518, F(5) = 606, F(6) = 694, so
  // R(q) = F(q) - 100 q: 114, 102, 116, 104, 118, 106, 94 -> R = 118 at job 4.
  TaskSet set = in_order(tasks_of({{26, 70}, {62, 100}}));
  set.tasks[1].deadline = 120;
  const Analysis analysis = analyse(set).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 118);
  EXPECT_EQ(analysis.tasks[1].worst_job, 4U);
  EXPECT_EQ(analysis.tasks[1].jobs, 7U);
  EXPECT_TRUE(analysis.schedulable());
}

TEST(ResponseTime, AnOverloadedSetIsUnschedulableWithoutEnd) {
  const Analysis analysis = analyse(in_order(tasks_of({{6, 10}, {5, 10}}))).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 6);
  EXPECT_EQ(analysis.tasks[1].response, unbounded);
  EXPECT_FALSE(analysis.schedulable());
}

// Issue #23's harmonic set, rate-monotonic: U = 5/20 + 10/40 + 40/80 = 1 exactly.
TaskSet issue_23_harmonic_set() { return in_order(tasks_of({{5, 20}, {10, 40}, {40, 80}})); }

TEST(ResponseTime, IssueTwentyThreesHarmonicSetAtUtilizationOneIsSchedulable) {
  // By hand, R = C + B + sum_hp ceil(R / Tj) Cj with B = 0, iterated from R = C:
  //   t0: R = 5.
  //   t1: 10 + ceil(10/20) 5 = 15 -> 10 + ceil(15/20) 5 = 15: R = 15.
  //   t2: 40 + 2*5 + 1*10 = 60 -> 40 + 3*5 + 2*10 = 75 -> 40 + 4*5 + 2*10 = 80 -> 80: R = 80 = D.
  // t2's busy period ends at 80, the hyperperiod, exactly where every task is released again.
  const Analysis analysis = analyse(issue_23_harmonic_set()).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 5);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 15);
  EXPECT_DOUBLE_EQ(analysis.tasks[2].response, 80);
  EXPECT_EQ(analysis.tasks[2].jobs, 1U);
  EXPECT_TRUE(analysis.schedulable());
}

TEST(ResponseTime, AFourTaskHarmonicSetAtUtilizationOneIsSchedulable) {
  // (2, 8), (4, 16), (8, 32), (8, 32): U = 1/4 + 1/4 + 1/4 + 1/4 = 1. By hand, R = C + sum_hp ceil(R / Tj) Cj:
  //   t0: R = 2.
  //   t1: 4 + ceil(4/8) 2 = 6 -> 4 + ceil(6/8) 2 = 6: R = 6.
  //   t2: 8 + 1*2 + 1*4 = 14 -> 8 + 2*2 + 1*4 = 16 -> 8 + 2*2 + 1*4 = 16: R = 16.
  //   t3: 8 + 1*2 + 1*4 + 1*8 = 22 -> 8 + 3*2 + 2*4 + 1*8 = 30 -> 8 + 4*2 + 2*4 + 1*8 = 32 -> 32: R = 32 = D.
  const Analysis analysis = analyse(in_order(tasks_of({{2, 8}, {4, 16}, {8, 32}, {8, 32}}))).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 2);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 6);
  EXPECT_DOUBLE_EQ(analysis.tasks[2].response, 16);
  EXPECT_DOUBLE_EQ(analysis.tasks[3].response, 32);
  EXPECT_TRUE(analysis.schedulable());
}

TEST(ResponseTime, OnePicosecondAboveUtilizationOneIsUnschedulable) {
  // t2's C one picosecond longer: U = 1 + 1.25e-8. Work then arrives faster than it is done: t2's busy period never
  // ends. t0 and t1 keep R = 5 and 15.
  TaskSet set = issue_23_harmonic_set();
  set.tasks[2].wcet = 40.000001;
  const Analysis analysis = analyse(set).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 5);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 15);
  EXPECT_EQ(analysis.tasks[2].response, unbounded);
  EXPECT_FALSE(analysis.schedulable());
}

TEST(ResponseTime, AtUtilizationOneBlockingOrJitterKeepTheBusyPeriodFromEnding) {
  // At U = 1 the work released in [0, w) is at least w; a picosecond of blocking or of jitter comes on top and is
  // never caught up. t2's first job alone already misses: 40 + B + 4*5 + 2*10 = 80 + 1 ps crosses 80, which adds
  // t0's and t1's next jobs.
  TaskSet blocked = issue_23_harmonic_set();
  blocked.core.masked_section = 0.000001;
  const Analysis blocked_analysis = analyse(blocked).value();
  EXPECT_DOUBLE_EQ(blocked_analysis.tasks[1].response, 15.000001);
  EXPECT_EQ(blocked_analysis.tasks[2].response, unbounded);
  TaskSet jittered = issue_23_harmonic_set();
  jittered.tasks[0].jitter = 0.000001;
  EXPECT_EQ(analyse(jittered).value().tasks[2].response, unbounded);
}

TEST(ResponseTime, TimesFinerThanAPicosecondAreAnError) {
  TaskSet set = issue_23_harmonic_set();
  set.tasks[1].period = 40.0000001;
  const auto analysis = analyse(set);
  ASSERT_FALSE(analysis.ok());
  EXPECT_EQ(analysis.error(),
            "task 't1': period_us is finer than a picosecond, the unit the analysis counts in (at most six decimals in "
            "us)");
}

TEST(ExactArithmetic, NaturalNumbersCarryAcrossWords) {
  // (2^64 - 1)^2 + 2 (2^64 - 1) + 1 = 2^128, built word by word the other way.
  constexpr std::uint64_t largest = ~std::uint64_t{0};
  Natural square{largest};
  square *= largest;
  Natural power{1};
  for (int word = 0; word < 4; ++word) power *= std::uint64_t{1} << 32;
  square += Natural{largest};
  square += Natural{largest};
  EXPECT_TRUE(square < power);
  square += Natural{1};
  EXPECT_TRUE(square <=> power == std::strong_ordering::equal);
  square += Natural{1};
  EXPECT_TRUE(square > power);
}

TEST(ResponseTime, AMissedDeadlineIsReportedWithItsResponse) {
  TaskSet set = in_order(tasks_of({{3, 7}, {3, 12}, {5, 20}}));
  set.tasks[2].deadline = 15;
  const Analysis analysis = analyse(set).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[2].response, 20);
  EXPECT_DOUBLE_EQ(analysis.tasks[2].slack(), -5);
  EXPECT_FALSE(analysis.schedulable());
}

TEST(ResponseTime, HandlersOfOneGroupDoNotPreemptEachOther) {
  // t0 and t1 share group 0 (t0 dispatched first, by sub-priority); t1 has started when t0 arrives: t0 waits.
  // t0: B = C1 = 4, R0 = 4 + 2 = 6. t1: preempted by nobody once started; starts after t0: R1 = 2 + 4 = 6.
  TaskSet set = tasks_of({{2, 10}, {4, 10}});
  set.tasks[0].priority = NvicPriority{0, 0};
  set.tasks[1].priority = NvicPriority{0, 1};
  const Analysis analysis = analyse(set).value();
  EXPECT_DOUBLE_EQ(analysis.tasks[0].blocking, 4);
  EXPECT_DOUBLE_EQ(analysis.tasks[0].response, 6);
  EXPECT_DOUBLE_EQ(analysis.tasks[1].response, 6);
}

TEST(ResponseTime, ATaskWithoutAPriorityIsAnError) {
  const auto analysis = analyse(tasks_of({{1, 10}}));
  ASSERT_FALSE(analysis.ok());
  EXPECT_NE(analysis.error().find("'t0' has no priority"), std::string::npos);
}

TEST(PriorityAssignment, DeadlineMonotonicReproducesTable4Point10) {
  const std::vector<NvicPriority> priorities = deadline_monotonic(thesis_robot_tasks());
  const int expected[] = {4, 5, 6, 7, 2, 1, 1, 9, 8, 8, 3, 3, 9};
  ASSERT_EQ(priorities.size(), 13U);
  for (std::size_t task = 0; task < 13; ++task) {
    EXPECT_EQ(priorities[task].group, expected[task]) << "task " << task;
    EXPECT_EQ(priorities[task].sub, 0);
  }
}

TEST(PriorityAssignment, TheThesisRobotMeetsEveryDeadlineExactly) {
  const TaskSet set = with_priorities(thesis_robot_tasks(), deadline_monotonic(thesis_robot_tasks()));
  const Analysis analysis = analyse(set).value();
  EXPECT_TRUE(analysis.schedulable());
  // Task 4 (TIM1, D = 100) waits for the hall handlers 5 and 6 (level 1) only: R = 4.1124 * 2 + 6.8316.
  EXPECT_NEAR(analysis.tasks[4].response, 15.0564, 1e-9);
  // Tasks 5 and 6 share level 1: each may wait for the other once it has started.
  EXPECT_NEAR(analysis.tasks[5].response, 8.2248, 1e-9);
  EXPECT_NEAR(analysis.tasks[6].response, 8.2248, 1e-9);
}

TEST(PriorityAssignment, AudsleyFindsAnOrderWhereDeadlineMonotonicFails) {
  // With jitter, DM is not optimal: t0 (C 2, T 10, D 6, J 4) must go first though t1 (C 3, T 12, D 5) is tighter.
  // DM: t1 first: R1 = 3; t0: R0 = 3 + 2 + 4 = 9 > 6. Swapped: R0 = 2 + 4 = 6; t1: w = 3 + 2 ceil((w + 4) / 10) = 5,
  // R1 = 5.
  TaskSet set = tasks_of({{2, 10}, {3, 12}});
  set.tasks[0].deadline = 6;
  set.tasks[0].jitter = 4;
  set.tasks[1].deadline = 5;
  EXPECT_FALSE(analyse(with_priorities(set, deadline_monotonic(set))).value().schedulable());
  const auto optimal = optimal_priorities(set);
  ASSERT_TRUE(optimal);
  EXPECT_LT((*optimal)[0].group, (*optimal)[1].group);
  EXPECT_TRUE(analyse(with_priorities(set, *optimal)).value().schedulable());
}

TEST(PriorityAssignment, AudsleySaysSoWhenNoOrderWorks) {
  EXPECT_FALSE(optimal_priorities(tasks_of({{6, 10}, {5, 10}})));
}

}  // namespace
}  // namespace duet::sched
