#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "duet/version.hpp"
#include "run_for_test.hpp"

namespace duet::cli {
namespace {

TEST(CommandLine, HelpListsEverySubcommand) {
  const Outcome outcome = run({"--help"});
  EXPECT_EQ(outcome.exit_code, ExitCode::success);
  for (const Subcommand& subcommand : subcommands()) {
    EXPECT_NE(outcome.out.find(std::string{subcommand.name}), std::string::npos) << subcommand.name;
    EXPECT_NE(outcome.out.find(std::string{subcommand.summary}), std::string::npos) << subcommand.name;
  }
  EXPECT_EQ(outcome.err, "");
}

TEST(CommandLine, EverySubcommandHasHelp) {
  for (const Subcommand& subcommand : subcommands()) {
    const Outcome outcome = run({std::string{subcommand.name}, "--help"});
    EXPECT_EQ(outcome.exit_code, ExitCode::success) << subcommand.name;
    EXPECT_NE(outcome.out.find("duet " + std::string{subcommand.name}), std::string::npos) << outcome.out;
    EXPECT_NE(outcome.out.find(std::string{subcommand.summary}), std::string::npos) << outcome.out;
  }
}

TEST(CommandLine, VersionPrintsTheProjectVersion) {
  const Outcome outcome = run({"--version"});
  EXPECT_EQ(outcome.exit_code, ExitCode::success);
  EXPECT_EQ(outcome.out, "duet " + std::string{version} + "\n");
}

TEST(CommandLine, UnknownSubcommandIsAUsageErrorNamingTheWord) {
  const Outcome outcome = run({"nonsense"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_EQ(outcome.err, "duet: 'nonsense' is not a duet command. See 'duet --help'.\n");
  EXPECT_EQ(outcome.out, "");
}

TEST(CommandLine, MistypedSubcommandGetsASuggestion) {
  const Outcome outcome = run({"shced", "tasks.yaml"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_EQ(outcome.err, "duet: 'shced' is not a duet command. Did you mean 'sched'? See 'duet --help'.\n");
}

TEST(CommandLine, UnknownOptionIsAUsageErrorNamingTheOption) {
  for (const std::vector<std::string>& arguments :
       {std::vector<std::string>{"--bogus"}, std::vector<std::string>{"sim", "--bogus"}}) {
    const Outcome outcome = run(arguments);
    EXPECT_EQ(outcome.exit_code, ExitCode::usage);
    EXPECT_NE(outcome.err.find("'--bogus'"), std::string::npos) << outcome.err;
  }
}

TEST(CommandLine, NoSubcommandIsAUsageError) {
  const Outcome outcome = run({});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_NE(outcome.err.find("duet --help"), std::string::npos) << outcome.err;
}

TEST(CommandLine, MonitorNeedsAnA2lFile) {
  const Outcome outcome = run({"monitor", "--xcp", "tcp://127.0.0.1:5555"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_NE(outcome.err.find("--a2l"), std::string::npos) << outcome.err;
}

// duet studio refuses what it cannot serve before it serves anything.
TEST(CommandLine, StudioNamesWhatIsWrongWithItsCommandLine) {
  const std::string model = std::string{DUET_SOURCE_DIR} + "/apps/pid_demo/pid_demo.yaml";
  Outcome outcome = run({"studio"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_NE(outcome.err.find("model"), std::string::npos) << outcome.err;
  outcome = run({"studio", "/nonexistent.yaml"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_NE(outcome.err.find("/nonexistent.yaml"), std::string::npos) << outcome.err;
  outcome = run({"studio", model, "--xcp", "serial://x"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_NE(outcome.err.find("--xcp"), std::string::npos) << outcome.err;
  outcome = run({"studio", model, "--listen", "0.0.0.0:0"});
  EXPECT_EQ(outcome.exit_code, ExitCode::usage);
  EXPECT_NE(outcome.err.find("--expose"), std::string::npos) << outcome.err;
}

}  // namespace
}  // namespace duet::cli
