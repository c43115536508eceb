// `duet sched` as a user types it, on the thesis robot's task file (docs/scheduling/balbot-tasks.yaml).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_for_test.hpp"

namespace duet::cli {
namespace {

const std::string robot = std::string{DUET_SOURCE_DIR} + "/docs/scheduling/balbot-tasks.yaml";

TEST(SchedCommand, TheRobotUnderTheThesisLevelsMeetsEveryDeadline) {
  const Outcome outcome = run({"sched", robot, "--assign", "dm"});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_NE(outcome.out.find("schedulable: every task meets its deadline"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("  model step: {group: 4, sub: 0}\n"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("  user data: {group: 9, sub: 0}\n"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("utilization C/T 0.18"), std::string::npos) << outcome.out;
}

TEST(SchedCommand, JsonAndTheTimeline) {
  const std::filesystem::path svg =
      std::filesystem::temp_directory_path() / ("duet_sched_" + std::to_string(::getpid()) + ".svg");
  const Outcome outcome = run({"sched", robot, "--assign", "opa", "--json", "--svg", svg.string()});
  ASSERT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  const nlohmann::json report = nlohmann::json::parse(outcome.out);
  EXPECT_TRUE(report["schedulable"].get<bool>());
  ASSERT_EQ(report["tasks"].size(), 13U);
  EXPECT_EQ(report["tasks"][0]["name"], "model step");
  EXPECT_LE(report["tasks"][0]["response_us"].get<double>(), 500.0);
  std::ifstream picture{svg};
  std::ostringstream read;
  read << picture.rdbuf();
  const std::string text = read.str();
  EXPECT_EQ(text.rfind("<svg", 0), 0U);
  EXPECT_NE(text.find("model step"), std::string::npos);
  std::filesystem::remove(svg);
}

TEST(SchedCommand, FailuresSayWhy) {
  const Outcome no_priorities = run({"sched", robot});
  EXPECT_EQ(no_priorities.exit_code, ExitCode::failure);
  EXPECT_NE(no_priorities.err.find("task 'model step' has no priority"), std::string::npos) << no_priorities.err;
  const Outcome missing = run({"sched", "/nonexistent.yaml"});
  EXPECT_EQ(missing.exit_code, ExitCode::failure);
  EXPECT_EQ(missing.err, "duet sched: /nonexistent.yaml: cannot open\n");
  const Outcome wrong = run({"sched", robot, "--assign", "rm"});
  EXPECT_EQ(wrong.exit_code, ExitCode::usage);

  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("duet_sched_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream{file} << "tasks:\n  - {name: a, wcet_us: 6, period_us: 10, priority: 0}\n"
                         "  - {name: b, wcet_us: 5, period_us: 10, priority: 1}\n";
  const Outcome overloaded = run({"sched", file.string()});
  EXPECT_EQ(overloaded.exit_code, ExitCode::failure);
  EXPECT_NE(overloaded.out.find("NOT schedulable: 1 of 2 tasks miss their deadlines"), std::string::npos)
      << overloaded.out;
  EXPECT_NE(overloaded.out.find("inf"), std::string::npos);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace duet::cli

namespace duet::cli {
namespace {

TEST(SchedCommand, MoreHandlersThanLevelsShareLevelsWhereDeadlinesAllow) {
  // Five handlers, four levels (2 bits): Audsley gives each its own level, so two must share. By hand, Audsley's
  // order (most urgent first) is t4, t0, t3, t1, t2 (the least urgent level goes to the first task that fits there).
  // Sharing the last two, t1 would wait for a started t2: R1 = 1 + 3 + 1 = 5 > 4. Sharing t3 and t1 instead: t1 waits
  // for at most a started t3: R1 = 1 + 2 + 1 = 4 <= 4; t3 = 4 <= 20; t2 = 5 <= 6. That is the fit.
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("duet_sched_levels_" + std::to_string(::getpid()) + ".yaml");
  std::ofstream{file} << "core: {priority_bits: 2}\ntasks:\n"
                         "  - {name: t0, wcet_us: 1, period_us: 10, deadline_us: 2}\n"
                         "  - {name: t1, wcet_us: 1, period_us: 10, deadline_us: 4}\n"
                         "  - {name: t2, wcet_us: 1, period_us: 10, deadline_us: 6}\n"
                         "  - {name: t3, wcet_us: 1, period_us: 20, deadline_us: 20}\n"
                         "  - {name: t4, wcet_us: 1, period_us: 40, deadline_us: 40}\n";
  const Outcome outcome = run({"sched", file.string(), "--assign", "opa"});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_NE(outcome.err.find("the core has 4 group levels; sharing levels to fit:\n  level 2: 't1' 't3'\n"),
            std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.out.find("  t2: {group: 3, sub: 0}\n"), std::string::npos) << outcome.out;
  EXPECT_NE(outcome.out.find("schedulable: every task meets its deadline"), std::string::npos) << outcome.out;
  // One level only: t0 (C 1, D 1) would wait for a started t1.
  std::ofstream{file, std::ios::trunc} << "core: {priority_bits: 0}\ntasks:\n"
                                          "  - {name: t0, wcet_us: 1, period_us: 10, deadline_us: 1}\n"
                                          "  - {name: t1, wcet_us: 1, period_us: 10, deadline_us: 10}\n";
  const Outcome impossible = run({"sched", file.string(), "--assign", "opa"});
  EXPECT_EQ(impossible.exit_code, ExitCode::failure);
  EXPECT_NE(impossible.err.find("no sharing of levels keeps every deadline"), std::string::npos) << impossible.err;
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace duet::cli
