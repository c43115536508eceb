// The duet-bridge program itself, as a separate process, end to end: firmware on a pty <-> duet-bridge <-> TCP <->
// duet's master. Which program: DUET_BRIDGE_PROGRAM (and DUET_BRIDGE_EMULATOR, e.g. qemu-arm-static for the armhf
// build); the test is skipped when the program is not there.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "duet/xcp/host/master.hpp"
#include "pty_firmware.hpp"

namespace duet::bridge {
namespace {

using namespace duet::xcp::host;

// A child process with its standard error in a pipe.
class Child {
 public:
  explicit Child(std::vector<std::string> arguments) {
    int pipe_ends[2];
    if (::pipe2(pipe_ends, O_CLOEXEC) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(pipe_ends[1], STDERR_FILENO);
      std::vector<char*> argv;
      for (std::string& argument : arguments) argv.push_back(argument.data());
      argv.push_back(nullptr);
      ::execvp(argv[0], argv.data());
      ::_exit(127);
    }
    ::close(pipe_ends[1]);
    stderr_ = pipe_ends[0];
  }
  ~Child() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    if (stderr_ >= 0) ::close(stderr_);
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  // Reads standard error until `marker` appears (or the time is up); returns what came after it on that line.
  std::string wait_for(const std::string& marker, std::chrono::seconds patience) {
    const auto deadline = std::chrono::steady_clock::now() + patience;
    while (std::chrono::steady_clock::now() < deadline) {
      const std::size_t found = output_.find(marker);
      if (found != std::string::npos) {
        const std::size_t end = output_.find('\n', found);
        if (end != std::string::npos) return output_.substr(found + marker.size(), end - found - marker.size());
      }
      pollfd readable{stderr_, POLLIN, 0};
      if (::poll(&readable, 1, 100) == 1) {
        char buffer[256];
        const ssize_t received = ::read(stderr_, buffer, sizeof(buffer));
        if (received <= 0) break;
        output_.append(buffer, static_cast<std::size_t>(received));
      }
    }
    return {};
  }
  // Sends SIGTERM, keeps what it still writes, and returns the exit code.
  int terminate() {
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    char buffer[256];
    ssize_t received = 0;
    while ((received = ::read(stderr_, buffer, sizeof(buffer))) > 0)
      output_.append(buffer, static_cast<std::size_t>(received));
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  [[nodiscard]] const std::string& output() const { return output_; }

 private:
  pid_t pid_ = -1;
  int stderr_ = -1;
  std::string output_;
};

TEST(BridgeProgram, RelaysEndToEndAndStopsCleanly) {
  const char* program = std::getenv("DUET_BRIDGE_PROGRAM");
  if (program == nullptr || !std::filesystem::exists(program)) GTEST_SKIP() << "no DUET_BRIDGE_PROGRAM to run";
  PtyFirmware firmware;
  firmware.start();
  std::vector<std::string> arguments;
  if (const char* emulator = std::getenv("DUET_BRIDGE_EMULATOR"); emulator != nullptr && *emulator != '\0') {
    arguments.emplace_back(emulator);
  }
  for (const char* argument : {program, "--channel"}) arguments.emplace_back(argument);
  arguments.push_back("tty:" + firmware.path());
  arguments.emplace_back("--listen");
  arguments.emplace_back("127.0.0.1:0");
  Child bridge{arguments};
  const std::string port = bridge.wait_for("listening for an XCP master on 127.0.0.1:", std::chrono::seconds{10});
  ASSERT_FALSE(port.empty()) << bridge.output();
  ASSERT_FALSE(bridge.wait_for(" open", std::chrono::seconds{10}).empty() &&
               bridge.output().find(" open") == std::string::npos);

  auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", static_cast<std::uint16_t>(std::stoi(port))},
                                     std::chrono::milliseconds{2000});
  ASSERT_TRUE(channel.ok()) << channel.error();
  Master master{std::move(channel).value(), std::chrono::milliseconds{2000}};
  ASSERT_TRUE(master.connect().ok());
  const std::array<std::uint8_t, 4> values{9, 8, 7, 6};
  ASSERT_TRUE(master.download(0, 0x2000, values).ok());
  EXPECT_EQ(master.upload(0, 0x2000, 4).value(), std::vector<std::uint8_t>(values.begin(), values.end()));

  ASSERT_TRUE(master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 4}}}}).ok());
  std::vector<std::uint32_t> counters;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds{10};
  while (std::chrono::steady_clock::now() < end) {
    auto samples = master.receive_samples(std::chrono::milliseconds{50});
    ASSERT_TRUE(samples.ok()) << samples.error();
    for (const DaqSample& sample : samples.value()) {
      std::uint32_t value = 0;
      for (std::size_t byte = 0; byte < 4; ++byte)
        value |= static_cast<std::uint32_t>(sample.bytes[byte]) << (8U * byte);
      counters.push_back(value);
    }
  }
  ASSERT_TRUE(master.stop_daq().ok());
  ASSERT_TRUE(master.disconnect().ok());
  ASSERT_GT(counters.size(), 9000U);
  std::size_t gaps = 0;
  for (std::size_t index = 1; index < counters.size(); ++index)
    gaps += counters[index] != counters[index - 1] + 1 ? 1U : 0U;
  EXPECT_EQ(gaps, 0U);
  EXPECT_EQ(master.channel().counter_gaps(), 0U);
  EXPECT_EQ(bridge.terminate(), 0) << bridge.output();
  EXPECT_NE(bridge.output().find("stopped; channel open"), std::string::npos) << bridge.output();
}

}  // namespace
}  // namespace duet::bridge
