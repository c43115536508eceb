// Task-set files: what they hold, and errors that name the line and the field.
#include "duet/sched/task_file.hpp"

#include <gtest/gtest.h>

namespace duet::sched {
namespace {

TEST(TaskFile, ReadsTheCoreAndTheTasks) {
  const auto set = parse_task_file(R"(
core:
  priority_bits: 4
  sub_priority_bits: 1
  entry_overhead_us: 0.06
  exit_overhead_us: 0.05
  masked_section_us: 2
  sections:
    - {ceiling: 1, longest_us: 0.4}
tasks:
  - name: step
    wcet_us: 99.818
    period_us: 1000
    deadline_us: 500
    source: TIM7
    irq: 55
    priority: {group: 3, sub: 1}
  - name: hall
    wcet_us: 4.1124
    period_us: 501.57
    jitter_us: 1.5
    priority: 2
)",
                                   "robot.yaml");
  ASSERT_TRUE(set.ok()) << set.error();
  EXPECT_EQ(set.value().core.sub_priority_bits, 1);
  EXPECT_DOUBLE_EQ(set.value().core.masked_section, 2);
  ASSERT_EQ(set.value().core.sections.size(), 1U);
  EXPECT_EQ(set.value().core.sections[0].ceiling, 1);
  EXPECT_DOUBLE_EQ(set.value().core.sections[0].longest, 0.4);
  ASSERT_EQ(set.value().tasks.size(), 2U);
  const Task& step = set.value().tasks[0];
  EXPECT_EQ(step.name, "step");
  EXPECT_DOUBLE_EQ(step.deadline, 500);
  EXPECT_EQ(step.source, "TIM7");
  EXPECT_EQ(step.irq, 55);
  EXPECT_EQ(step.priority, (NvicPriority{3, 1}));
  const Task& hall = set.value().tasks[1];
  EXPECT_DOUBLE_EQ(hall.deadline, 501.57);  // D defaults to T
  EXPECT_DOUBLE_EQ(hall.jitter, 1.5);
  EXPECT_EQ(hall.priority, (NvicPriority{2, 0}));
}

std::string error_of(const std::string& text) {
  const auto set = parse_task_file(text, "tasks.yaml");
  return set.ok() ? "(no error)" : set.error();
}

TEST(TaskFile, ErrorsNameTheLineAndTheField) {
  EXPECT_EQ(error_of("tasks:\n  - name: a\n    wcet_us: x\n    period_us: 10\n"),
            "tasks.yaml:3: task 'a': wcet_us: expected a number, got 'x'");
  EXPECT_EQ(error_of("tasks:\n  - name: a\n    period_us: 10\n"), "tasks.yaml:2: task 'a': 'wcet_us' is missing");
  EXPECT_EQ(error_of("tasks:\n  - name: a\n    wcet_us: 1\n    period_us: 10\n    wcte_us: 2\n"),
            "tasks.yaml:5: task 'a': unknown field 'wcte_us' (known: name, wcet_us, period_us, deadline_us, jitter_us, "
            "source, irq, priority)");
  EXPECT_EQ(error_of("tasks:\n  - wcet_us: 1\n    period_us: 10\n"), "tasks.yaml:2: task 1: 'name' is missing");
  EXPECT_EQ(error_of("core:\n  priority_bits: 9\ntasks:\n  - {name: a, wcet_us: 1, period_us: 2}\n"),
            "tasks.yaml:2: core: priority_bits: 9 is outside 0..8");
  EXPECT_EQ(error_of("tasks:\n  - {name: a, wcet_us: 1, period_us: 2}\n  - {name: a, wcet_us: 1, period_us: 2}\n"),
            "tasks.yaml:3: task 'a' is named twice");
  EXPECT_EQ(error_of("tasks: [\n"), "tasks.yaml:2: not YAML: end of sequence flow not found");
  EXPECT_EQ(error_of("core: {}\n"), "tasks.yaml:1: 'tasks' is missing or empty: expected a list of tasks");
  EXPECT_EQ(error_of("- 1\n"), "tasks.yaml: expected a map with 'core' and 'tasks'");
}

TEST(TaskFile, ImpossibleValuesAreRejectedWithAReason) {
  EXPECT_EQ(error_of("tasks:\n  - {name: a, wcet_us: -1, period_us: 2}\n"),
            "tasks.yaml:2: task 'a': wcet_us: -1 is negative; times are never negative");
  EXPECT_EQ(error_of("tasks:\n  - {name: a, wcet_us: 3, period_us: 2}\n"),
            "tasks.yaml:2: task 'a': wcet_us 3 exceeds period_us 2 while the deadline is within the period: it could "
            "never be met");
  EXPECT_EQ(error_of("tasks:\n  - {name: a, wcet_us: 0, period_us: 2}\n"),
            "tasks.yaml:2: task 'a': wcet_us must be more than 0");
  EXPECT_EQ(error_of("tasks:\n  - {name: a, wcet_us: 1, period_us: 2, priority: 16}\n"),
            "tasks.yaml:2: task 'a': priority: expected a group priority 0..15 or {group, sub}");
  EXPECT_EQ(
      error_of("core: {sub_priority_bits: 2}\ntasks:\n  - {name: a, wcet_us: 1, period_us: 2, priority: {group: 1, "
               "sub: 4}}\n"),
      "tasks.yaml:3: task 'a': priority: sub: 4 is outside 0..3");
  EXPECT_EQ(error_of("tasks:\n  - {name: a, wcet_us: 0.1234567, period_us: 2}\n"),
            "tasks.yaml:2: task 'a': wcet_us: 0.1234567 is finer than a picosecond, the unit the analysis counts in "
            "(at most six decimals in us)");
  EXPECT_EQ(error_of("tasks:\n  - {name: a, wcet_us: 1, period_us: 1e20}\n"),
            "tasks.yaml:2: task 'a': period_us: 1e20 is longer than 2^61 ps (about 26.7 days), the longest time the "
            "analysis counts");
  // C > T is possible with D > T (arbitrary deadlines): accepted, the analysis decides.
  EXPECT_EQ(error_of("tasks:\n  - {name: a, wcet_us: 5, period_us: 4, deadline_us: 9}\n"), "(no error)");
}

TEST(TaskFile, AMissingFileIsNamed) {
  const auto set = load_task_file("/nonexistent/tasks.yaml");
  ASSERT_FALSE(set.ok());
  EXPECT_EQ(set.error(), "/nonexistent/tasks.yaml: cannot open");
}

}  // namespace
}  // namespace duet::sched
