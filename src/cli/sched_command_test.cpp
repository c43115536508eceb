// `duet sched` as a user types it, on the thesis robot's task file (docs/scheduling/balbot-tasks.yaml).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

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
  const std::string text{std::istreambuf_iterator<char>{picture}, {}};
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
