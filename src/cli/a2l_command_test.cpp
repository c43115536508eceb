#include <gtest/gtest.h>

#include <string>

#include "run_for_test.hpp"

namespace duet::cli {
namespace {

std::string testing_folder() { return std::string{DUET_SOURCE_DIR} + "/src/xcp/host/testing"; }

TEST(A2lCommand, AValidFilePassesSilently) {
  const Outcome outcome = run({"a2l", "check", testing_folder() + "/engine.a2l"});
  EXPECT_EQ(outcome.exit_code, ExitCode::success);
  EXPECT_EQ(outcome.out, "");
}

TEST(A2lCommand, ProblemsAreLinesNamingThePlaceAndFailTheCommand) {
  const Outcome outcome = run({"a2l", "check", testing_folder() + "/engine.a2l", "/nonexistent.a2l"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_EQ(outcome.out, "/nonexistent.a2l: error: cannot open\n");
}

TEST(A2lCommand, NeedsAFile) {
  EXPECT_EQ(run({"a2l", "check"}).exit_code, ExitCode::usage);
  EXPECT_EQ(run({"a2l"}).exit_code, ExitCode::usage);
}

}  // namespace
}  // namespace duet::cli
