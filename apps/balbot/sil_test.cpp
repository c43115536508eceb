// Software in the loop: balbot_sil, the generated firmware on the PC, records what duet sim records for the model,
// bit for bit; over the link to `duet plant serve balbot` it balances the robot and ends where the run in one process
// ends. Both programs run as child processes, as a user runs them.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "duet/link/stream.hpp"
#include "duet/link/tcp.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/plant/balbot/balbot_scenario.hpp"
#include "duet/plot/csv.hpp"
#include "duet/support/text_file.hpp"
#include "sil_run.hpp"

extern char** environ;  // NOLINT(readability-redundant-declaration): for posix_spawn

namespace duet::sil {
namespace {

using namespace std::chrono_literals;

// A file in the temporary folder, removed at the end of the test.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / ("balbot_sil_test_" + std::to_string(::getpid()) + "_" + name)) {
  }
  ~TemporaryFile() { std::filesystem::remove(path_); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  [[nodiscard]] std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

// A program running as a child process: its standard output on a pipe (read line by line while it runs), its
// standard error in a file (read once it is done, so that a long report cannot block it).
class Program {
 public:
  Program(const std::string& program, const std::vector<std::string>& arguments, const std::string& name)
      : errors_{name + ".err"} {
    int out[2] = {-1, -1};
    if (::pipe2(out, O_CLOEXEC) != 0) return;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errors_.path().c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    std::vector<std::string> words{program};
    words.insert(words.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    argv.reserve(words.size() + 1);
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, program.c_str(), &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    output_ = std::make_unique<link::FdStream>(out[0], out[0], 60s);
  }
  // A program still running when a test gives up (a server waiting for a firmware that failed) is stopped.
  ~Program() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      (void)wait();
    }
  }
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  [[nodiscard]] bool started() const { return pid_ > 0; }
  // The next line of its standard output, without the newline ("" at its end).
  std::string line() {
    std::string text;
    std::uint8_t byte = 0;
    while (output_->read_exactly({&byte, 1}).ok() && byte != '\n') text += static_cast<char>(byte);
    return text;
  }
  // Waits for it to end: its exit code (128 + the signal when a signal ended it).
  int wait() {
    int status = 0;
    ::waitpid(std::exchange(pid_, -1), &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  // Its standard error: call after wait().
  [[nodiscard]] std::string errors() const {
    auto text = read_text_file(errors_.path());
    return text ? text.value() : "";
  }

 private:
  TemporaryFile errors_;
  pid_t pid_ = -1;
  std::unique_ptr<link::FdStream> output_;
};

Program balbot_sil(const std::vector<std::string>& arguments, const std::string& name) {
  return Program{BALBOT_SIL_PROGRAM, arguments, name};
}

plant::BalbotScenario release_scenario() {
  auto scenario = plant::load_balbot_scenario(DUET_BALBOT_SCENARIO);
  EXPECT_TRUE(scenario.ok()) << scenario.error();
  return scenario ? scenario.value() : plant::BalbotScenario{};
}

// The number after `label` in balbot_sil's last line ("...; final theta 0.0123 deg; ..."), exactly as written.
double number_after(const std::string& line, const std::string& label) {
  const std::size_t at = line.find(label);
  EXPECT_NE(at, std::string::npos) << label << " in: " << line;
  return at == std::string::npos ? NAN : std::strtod(line.c_str() + at + label.size(), nullptr);
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

TEST(BalbotSil, TheFirmwareOnThePcRecordsWhatDuetSimRecords) {
  const TemporaryFile csv{"firmware.csv"};
  Program program = balbot_sil(
      {"--plant", "balbot", "--scenario", DUET_BALBOT_SCENARIO, "--duration", "10", "--csv", csv.path()}, "same");
  ASSERT_TRUE(program.started());
  const std::string summary = program.line();
  ASSERT_EQ(program.wait(), 0) << program.errors();
  EXPECT_TRUE(summary.starts_with("balbot_sil: 10001 ticks (lock-step, plant balbot in process); final theta "))
      << summary;

  auto model = model::load_model(DUET_BALBOT_MODEL);
  ASSERT_TRUE(model.ok()) << model.error();
  const model::ProgramBuild build = model::build_program(model.value());
  ASSERT_TRUE(build.program.has_value());
  const auto robot = plant::make_balbot_plant(release_scenario());
  model::SimulationOptions options;
  options.duration_s = 10;
  options.record_plant = false;  // the firmware's measurable signals only
  auto simulated = model::simulate(*build.program, *robot, options);
  ASSERT_TRUE(simulated.ok()) << simulated.error();
  const std::string expected = model::to_csv(simulated.value().recording);

  auto written = read_text_file(csv.path());
  ASSERT_TRUE(written.ok()) << written.error();
  const std::string& actual = written.value();
  if (actual != expected) {  // say where, not the megabytes
    const auto [differs, _] = std::mismatch(expected.begin(), expected.end(), actual.begin(), actual.end());
    const auto line = std::count(expected.begin(), differs, '\n') + 1;
    const auto start = expected.rfind('\n', static_cast<std::size_t>(differs - expected.begin()));
    const auto begin = start == std::string::npos ? 0 : start + 1;
    FAIL() << "line " << line << " differs; duet sim: " << expected.substr(begin, expected.find('\n', begin) - begin);
  }
  EXPECT_GT(number_after(summary, "largest |theta| after 4 s "), 0.0);  // it moved, and stayed up:
  EXPECT_LT(number_after(summary, "largest |theta| after 4 s "), 1.0);
}

TEST(BalbotSil, OverTheLinkItBalancesAndEndsWhereTheRunInOneProcessEnds) {
  const TemporaryFile robot_csv{"robot.csv"};
  Program server{DUET_PROGRAM,
                 {"plant", "serve", "balbot", "--scenario", DUET_BALBOT_SCENARIO, "--listen", "127.0.0.1:0", "--once",
                  "--csv", robot_csv.path()},
                 "server"};
  ASSERT_TRUE(server.started());
  const std::string listening = server.line();
  const std::string prefix = "plant balbot listening on ";
  ASSERT_TRUE(listening.starts_with(prefix)) << listening;
  const std::string address = listening.substr(prefix.size());

  Program firmware = balbot_sil({"--link", address, "--duration", "5"}, "firmware");
  ASSERT_TRUE(firmware.started());
  const std::string summary = firmware.line();
  ASSERT_EQ(firmware.wait(), 0) << firmware.errors();
  const std::string served = server.line();
  ASSERT_EQ(server.wait(), 0) << server.errors();
  EXPECT_TRUE(summary.starts_with("balbot_sil: 5001 ticks (lock-step, plant at " + address + "); final theta "))
      << summary;
  EXPECT_NE(served.find(": 5001 ticks, "), std::string::npos) << served;

  // The robot's own view (the server's CSV): standing, 2 s after the release and on.
  auto text = read_text_file(robot_csv.path());
  ASSERT_TRUE(text.ok()) << text.error();
  auto robot = plot::read_csv(text.value(), robot_csv.path());
  ASSERT_TRUE(robot.ok()) << robot.error();
  ASSERT_EQ(robot.value().time.size(), 5001U);
  const auto theta = std::find_if(robot.value().series.begin(), robot.value().series.end(),
                                  [](const plot::Series& series) { return series.name == "theta_deg"; });
  ASSERT_NE(theta, robot.value().series.end());
  EXPECT_EQ(theta->values.front(), 5.0);  // held at 5 degrees at first
  double largest = 0;
  for (std::size_t k = 4000; k < theta->values.size(); ++k) largest = std::max(largest, std::abs(theta->values[k]));
  EXPECT_LT(largest, 1.0);

  // In lock-step the link changes nothing: the firmware ends where it ends against the robot in this process.
  const auto local = plant::make_balbot_plant(release_scenario());
  auto in_process = run_sil(*local, {.duration_s = 5});
  ASSERT_TRUE(in_process.ok()) << in_process.error();
  EXPECT_EQ(in_process.value().ticks, 5001U);
  EXPECT_TRUE(same_bits(number_after(summary, "final theta "), in_process.value().final_theta_deg))
      << summary << " against " << in_process.value().final_theta_deg;
  ASSERT_TRUE(in_process.value().largest_theta_after_4_s_deg.has_value());
  EXPECT_TRUE(
      same_bits(number_after(summary, "largest |theta| after 4 s "), *in_process.value().largest_theta_after_4_s_deg))
      << summary;
}

TEST(BalbotSil, BadCommandLinesAndAMissingPlantSayWhatIsWrong) {
  Program both = balbot_sil({"--plant", "balbot", "--link", "127.0.0.1:5601"}, "both");
  EXPECT_EQ(both.wait(), 2);
  EXPECT_NE(both.errors().find("excludes"), std::string::npos) << both.errors();

  Program scenario_alone = balbot_sil({"--scenario", DUET_BALBOT_SCENARIO}, "scenario");
  EXPECT_EQ(scenario_alone.wait(), 2);
  EXPECT_NE(scenario_alone.errors().find("requires --plant"), std::string::npos) << scenario_alone.errors();

  Program bad_address = balbot_sil({"--link", "localhost"}, "address");
  EXPECT_EQ(bad_address.wait(), 2);
  EXPECT_NE(bad_address.errors().find("'localhost' is not HOST:PORT"), std::string::npos) << bad_address.errors();

  Program unknown_plant = balbot_sil({"--plant", "balbott"}, "unknown");
  EXPECT_EQ(unknown_plant.wait(), 1);
  EXPECT_EQ(unknown_plant.errors(), "balbot_sil: unknown plant 'balbott' (did you mean 'balbot'?)\n");

  // A port nobody listens on: the one a listener had a moment ago.
  std::string address;
  {
    auto listener = link::TcpListener::open({"127.0.0.1", 0});
    ASSERT_TRUE(listener.ok()) << listener.error();
    address = link::to_string(listener.value().address());
  }
  Program nobody = balbot_sil({"--link", address, "--duration", "1"}, "nobody");
  EXPECT_EQ(nobody.line(), "");
  EXPECT_EQ(nobody.wait(), 1);
  EXPECT_TRUE(nobody.errors().starts_with("balbot_sil: ")) << nobody.errors();
  EXPECT_NE(nobody.errors().find(address), std::string::npos) << nobody.errors();
}

TEST(BalbotSil, InRealTimeTheTicksFollowTheWallClock) {
  const auto start = std::chrono::steady_clock::now();
  Program program = balbot_sil({"--plant", "balbot", "--duration", "0.3", "--real-time"}, "real_time");
  const std::string summary = program.line();
  EXPECT_EQ(program.wait(), 0) << program.errors();
  EXPECT_GE(std::chrono::steady_clock::now() - start, 300ms);
  EXPECT_TRUE(summary.starts_with("balbot_sil: 301 ticks (real time, ")) << summary;
  EXPECT_NE(summary.find("largest |theta| after 4 s none"), std::string::npos) << summary;
}

}  // namespace
}  // namespace duet::sil
