// The duet-bridge program itself, as a separate process, end to end: firmware on a pty <-> duet-bridge <-> TCP <->
// `duet xcp` (DUET_PROGRAM) and duet's master. Which program: DUET_BRIDGE_PROGRAM (and DUET_BRIDGE_EMULATOR, e.g.
// qemu-arm-static for the armhf build); the test is skipped when the program is not there.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/master.hpp"
#include "pty_application.hpp"
#include "pty_firmware.hpp"
#include "websocket_client.hpp"

namespace duet::bridge {
namespace {

using namespace duet::xcp::host;
using duet::dashboard::testing::WebSocketClient;

// How long a test waits for what must come (a line of the bridge's, an answer): only a guard against a hang. CI runs
// the tests of every build at once on two cores, and the armhf bridge under qemu-arm.
constexpr std::chrono::seconds patience{20};

// A child process with its standard input, output and error in pipes.
class Child {
 public:
  explicit Child(std::vector<std::string> arguments) {
    int error_pipe[2];
    int output_pipe[2];
    int input_pipe[2];
    if (::pipe2(error_pipe, O_CLOEXEC) != 0 || ::pipe2(output_pipe, O_CLOEXEC) != 0 ||
        ::pipe2(input_pipe, O_CLOEXEC) != 0) {
      return;
    }
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(error_pipe[1], STDERR_FILENO);
      ::dup2(output_pipe[1], STDOUT_FILENO);
      ::dup2(input_pipe[0], STDIN_FILENO);
      std::vector<char*> argv;
      for (std::string& argument : arguments) argv.push_back(argument.data());
      argv.push_back(nullptr);
      ::execvp(argv[0], argv.data());
      ::_exit(127);
    }
    ::close(error_pipe[1]);
    ::close(output_pipe[1]);
    ::close(input_pipe[0]);
    stderr_ = error_pipe[0];
    stdout_ = output_pipe[0];
    stdin_ = input_pipe[1];
  }
  ~Child() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    for (const int descriptor : {stderr_, stdout_, stdin_}) {
      if (descriptor >= 0) ::close(descriptor);
    }
  }
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;

  void write_line(const std::string& line) const { write(line + "\n"); }
  void write(const std::string& text) const {
    [[maybe_unused]] const ssize_t written = ::write(stdin_, text.data(), text.size());
  }
  // Ends its standard input: it reads end of file.
  void close_input() {
    ::close(stdin_);
    stdin_ = -1;
  }
  // Stops reading its standard output, as a reader that goes away: its next write there fails.
  void close_output() {
    ::close(stdout_);
    stdout_ = -1;
  }
  // Reads standard output until `lines` complete lines have come (or the patience is up).
  std::vector<std::string> read_lines(std::size_t lines) {
    const auto deadline = std::chrono::steady_clock::now() + patience;
    std::vector<std::string> complete;
    while (complete.size() < lines && std::chrono::steady_clock::now() < deadline) {
      const std::size_t end = stdout_text_.find('\n');
      if (end != std::string::npos) {
        complete.push_back(stdout_text_.substr(0, end));
        stdout_text_.erase(0, end + 1);
        continue;
      }
      pollfd readable{stdout_, POLLIN, 0};
      if (::poll(&readable, 1, 100) == 1) {
        char buffer[4096];
        const ssize_t received = ::read(stdout_, buffer, sizeof(buffer));
        if (received <= 0) break;
        stdout_text_.append(buffer, static_cast<std::size_t>(received));
      }
    }
    return complete;
  }

  // Reads standard error until `marker` appears (or the patience is up); returns what came after it on that line.
  std::string wait_for(const std::string& marker) {
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
  // Waits for the child to end by itself; returns its exit code, and keeps what it wrote (small outputs only: a
  // full pipe would stop it).
  int wait_for_exit() {
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    char buffer[4096];
    ssize_t received = 0;
    while ((received = ::read(stderr_, buffer, sizeof(buffer))) > 0)
      output_.append(buffer, static_cast<std::size_t>(received));
    while ((received = ::read(stdout_, buffer, sizeof(buffer))) > 0) {
      stdout_text_.append(buffer, static_cast<std::size_t>(received));
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }
  [[nodiscard]] const std::string& standard_output() const { return stdout_text_; }
  [[nodiscard]] const std::string& output() const { return output_; }
  [[nodiscard]] pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  int stderr_ = -1;
  int stdout_ = -1;
  int stdin_ = -1;
  std::string output_;
  std::string stdout_text_;
};

// The command that runs the bridge program (under its emulator, if any); none if there is no program.
std::optional<std::vector<std::string>> bridge_command() {
  const char* program = std::getenv("DUET_BRIDGE_PROGRAM");
  if (program == nullptr || !std::filesystem::exists(program)) return std::nullopt;
  std::vector<std::string> command;
  if (const char* emulator = std::getenv("DUET_BRIDGE_EMULATOR"); emulator != nullptr && *emulator != '\0') {
    command.emplace_back(emulator);
  }
  command.emplace_back(program);
  return command;
}

// `duet xcp ...` against the bridge at `port`, with the pty firmware's A2L; returns the exit code, keeps the output.
struct DuetRun {
  int exit_code = -1;
  std::string output;  // standard output, then standard error
};
DuetRun duet_xcp(std::vector<std::string> arguments, std::uint16_t port, const std::filesystem::path& a2l) {
  const char* duet = std::getenv("DUET_PROGRAM");
  std::vector<std::string> command{duet != nullptr ? duet : "duet", "xcp"};
  command.insert(command.end(), arguments.begin(), arguments.end());
  command.insert(command.end(), {"--a2l", a2l.string(), "--connect", "tcp://127.0.0.1:" + std::to_string(port)});
  Child run{command};
  DuetRun result;
  result.exit_code = run.wait_for_exit();
  result.output = run.standard_output() + run.output();
  return result;
}

// The pty firmware as an A2L describes it: the step counter, sampled by event 0 every millisecond, and a gain.
std::filesystem::path write_firmware_a2l() {
  A2lDescription a2l;
  a2l.module = "pty_firmware";
  a2l.memory.push_back({.name = "parameters", .address = 0x2000, .size = 8});
  Variable counter;
  counter.name = "counter";
  counter.type = DataType::uint32;
  counter.address = 0x1000;
  counter.maximum = 4294967295.0;
  a2l.measurements.push_back(counter);
  Variable gain;
  gain.name = "gain";
  gain.type = DataType::uint32;
  gain.address = 0x2000;
  gain.maximum = 1000;
  a2l.characteristics.push_back(gain);
  EventInfo event;
  event.name = "1 ms";
  event.time_cycle = 1;
  a2l.events.push_back(event);
  a2l.max_dto = 256;
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("duet_pty_firmware_" + std::to_string(::getpid()) + ".a2l");
  std::ofstream{file} << write_a2l(a2l);
  return file;
}

// The acceptance path: host-built firmware with the XCP slave <-> pty <-> duet-bridge <-> TCP <-> `duet xcp`.
TEST(BridgeProgram, DuetXcpThroughTheBridgeReadsWritesAndRecordsTenSecondsWithoutLoss) {
  auto arguments = bridge_command();
  if (!arguments) GTEST_SKIP() << "no DUET_BRIDGE_PROGRAM to run";
  PtyFirmware firmware;
  firmware.start();
  arguments->insert(arguments->end(), {"--channel", "tty:" + firmware.path(), "--listen", "127.0.0.1:0"});
  Child bridge{*arguments};
  const std::string port_text = bridge.wait_for("listening for an XCP master on 127.0.0.1:");
  ASSERT_FALSE(port_text.empty()) << bridge.output();
  ASSERT_FALSE(bridge.wait_for(" open").empty() && bridge.output().find(" open") == std::string::npos);
  const auto port = static_cast<std::uint16_t>(std::stoi(port_text));
  const std::filesystem::path a2l = write_firmware_a2l();

  const DuetRun info = duet_xcp({"info"}, port, a2l);
  EXPECT_EQ(info.exit_code, 0) << info.output;
  const DuetRun write = duet_xcp({"write", "gain=42"}, port, a2l);
  EXPECT_EQ(write.exit_code, 0) << write.output;
  EXPECT_EQ(firmware.parameters[0], 42);
  const DuetRun read = duet_xcp({"read", "gain"}, port, a2l);
  EXPECT_EQ(read.exit_code, 0) << read.output;
  EXPECT_NE(read.output.find("42"), std::string::npos) << read.output;

  const std::filesystem::path csv = a2l.string() + ".csv";
  const DuetRun record = duet_xcp(
      {"record", "--signal", "counter", "--event", "0", "--duration", "10", "--output", csv.string()}, port, a2l);
  EXPECT_EQ(record.exit_code, 0) << record.output;
  std::ifstream lines{csv};
  std::string line;
  std::getline(lines, line);  // the header
  std::vector<std::uint64_t> counters;
  while (std::getline(lines, line)) counters.push_back(std::stoull(line.substr(line.find(',') + 1)));
  EXPECT_GT(counters.size(), 9500U) << record.output;
  std::size_t gaps = 0;
  for (std::size_t index = 1; index < counters.size(); ++index)
    gaps += counters[index] != counters[index - 1] + 1 ? 1U : 0U;
  EXPECT_EQ(gaps, 0U) << record.output;
  std::filesystem::remove(csv);
  std::filesystem::remove(a2l);

  EXPECT_EQ(bridge.terminate(), 0) << bridge.output();
  EXPECT_NE(bridge.output().find("stopped; channel open"), std::string::npos) << bridge.output();
  EXPECT_NE(bridge.output().find("DAQ frames dropped 0"), std::string::npos) << bridge.output();
  EXPECT_NE(bridge.output().find("commands refused 0, unanswered 0"), std::string::npos) << bridge.output();
}

// What the kernel says of a process: its resident memory in kB and its open descriptors.
struct Footprint {
  std::size_t resident_kb = 0;
  std::size_t descriptors = 0;
};
Footprint footprint(pid_t pid) {
  Footprint result;
  std::ifstream status{"/proc/" + std::to_string(pid) + "/status"};
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmRSS:", 0) == 0) result.resident_kb = std::stoul(line.substr(6));
  }
  // The fewest descriptors seen over half a second: the last master's socket closes when the bridge has seen it go.
  const std::filesystem::path descriptors{"/proc/" + std::to_string(pid) + "/fd"};
  result.descriptors = std::numeric_limits<std::size_t>::max();
  for (int look = 0; look < 25; ++look) {
    result.descriptors = std::min(
        result.descriptors, static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator{descriptors},
                                                                   std::filesystem::directory_iterator{})));
    std::this_thread::sleep_for(std::chrono::milliseconds{20});
  }
  return result;
}

TEST(BridgeProgram, MemoryAndDescriptorsStayBoundedOverAThousandMasters) {
  auto arguments = bridge_command();
  if (!arguments) GTEST_SKIP() << "no DUET_BRIDGE_PROGRAM to run";
  PtyFirmware firmware;
  firmware.start();
  arguments->insert(arguments->end(), {"--channel", "tty:" + firmware.path(), "--listen", "127.0.0.1:0"});
  Child bridge{*arguments};
  const std::string port_text = bridge.wait_for("listening for an XCP master on 127.0.0.1:");
  ASSERT_FALSE(port_text.empty()) << bridge.output();
  const auto port = static_cast<std::uint16_t>(std::stoi(port_text));
  // Half the masters start DAQ and vanish without a word; the others disconnect properly.
  const auto cycle = [port](int number) {
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", port}, patience);
    if (!channel.ok()) return false;
    Master master{std::move(channel).value(), patience};
    if (!master.connect().ok()) return false;
    if (number % 2 == 0) return master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 4}}}}).ok();
    return master.disconnect().ok();
  };
  for (int number = 0; number < 50; ++number) ASSERT_TRUE(cycle(number)) << "warm-up " << number;
  const Footprint before = footprint(bridge.pid());
  for (int number = 0; number < 1000; ++number) ASSERT_TRUE(cycle(number)) << "cycle " << number;
  const Footprint after = footprint(bridge.pid());
  EXPECT_EQ(after.descriptors, before.descriptors);
  EXPECT_LT(after.resident_kb, before.resident_kb + 1024) << before.resident_kb << " kB before";
  EXPECT_TRUE(cycle(1));
  EXPECT_EQ(bridge.terminate(), 0) << bridge.output();
}

TEST(BridgeProgram, OffersTheApplicationChannelAsCsvAndOverWebSocket) {
  auto arguments = bridge_command();
  if (!arguments) GTEST_SKIP() << "no DUET_BRIDGE_PROGRAM to run";
  PtyApplication application;
  application.start();
  arguments->insert(arguments->end(),
                    {"--app-channel", "tty:" + application.path(), "--websocket", "127.0.0.1:0", "--csv"});
  Child bridge{*arguments};
  const std::string port = bridge.wait_for("WebSocket clients on 127.0.0.1:");
  ASSERT_FALSE(port.empty()) << bridge.output();

  // CSV on standard output: a header from the description, then a line per sample at 100 Hz.
  const std::vector<std::string> lines = bridge.read_lines(101);
  ASSERT_EQ(lines.size(), 101U) << bridge.output();
  EXPECT_EQ(lines[0], "sample,theta [deg],battery [V],distance [cm]");
  EXPECT_NE(lines[100].find(",7.4000001,"), std::string::npos) << lines[100];  // a float's every digit
  std::size_t gaps = 0;
  for (std::size_t line = 1; line < lines.size(); ++line) {  // the header once, then samples only
    ASSERT_TRUE(!lines[line].empty() && std::isdigit(static_cast<unsigned char>(lines[line][0])) != 0) << lines[line];
  }
  for (std::size_t line = 2; line < lines.size(); ++line) {
    gaps += std::stoul(lines[line]) != std::stoul(lines[line - 1]) + 1 ? 1U : 0U;
  }
  EXPECT_EQ(gaps, 0U);

  // Gains from standard input, and over WebSocket.
  bridge.write_line("P=0.05");
  bridge.write_line("I=0.01");
  bridge.write_line("Q=1");
  EXPECT_FALSE(bridge.wait_for("parameter I = ").empty()) << bridge.output();
  EXPECT_FALSE(bridge.wait_for("no parameter named 'Q'").empty() &&
               bridge.output().find("no parameter named 'Q'") == std::string::npos);
  EXPECT_FLOAT_EQ(application.p, 0.05F);
  EXPECT_FLOAT_EQ(application.i, 0.01F);
  WebSocketClient client{static_cast<std::uint16_t>(std::stoi(port))};
  ASSERT_TRUE(client.next("description"));
  client.send({{"type", "set"}, {"name", "D"}, {"value", 0.02}});
  const auto answer = client.answer_on("D");
  ASSERT_TRUE(answer);
  EXPECT_EQ((*answer)["status"], "applied");
  EXPECT_FLOAT_EQ(application.d, 0.02F);

  EXPECT_EQ(bridge.terminate(), 0) << bridge.output();
  EXPECT_NE(bridge.output().find("stopped; application channel"), std::string::npos) << bridge.output();
}

// The CSV service alone, on the robot's application on a pty; the bridge has printed the CSV header when it returns.
struct CsvBridge {
  PtyApplication application;
  std::optional<Child> bridge;
};
void start_csv_bridge(CsvBridge& csv, const std::vector<std::string>& program) {
  csv.application.start();
  std::vector<std::string> arguments = program;
  arguments.insert(arguments.end(), {"--app-channel", "tty:" + csv.application.path(), "--no-websocket", "--csv"});
  csv.bridge.emplace(arguments);
  ASSERT_EQ(csv.bridge->read_lines(1).size(), 1U) << csv.bridge->output();
}

TEST(BridgeProgram, AnOverLongInputLineIsReportedCountedAndSkipped) {
  auto arguments = bridge_command();
  if (!arguments) GTEST_SKIP() << "no DUET_BRIDGE_PROGRAM to run";
  CsvBridge csv;
  ASSERT_NO_FATAL_FAILURE(start_csv_bridge(csv, *arguments));
  Child& bridge = *csv.bridge;
  bridge.write_line(std::string(5000, 'x'));
  bridge.write_line("P=0.05");
  bridge.write("Q=1\nI=0.01");  // the last line without a newline, then the end of the input
  bridge.close_input();
  EXPECT_FALSE(bridge.wait_for("standard input line 1: longer than 4096 bytes").empty() &&
               bridge.output().find("standard input line 1: longer") == std::string::npos)
      << bridge.output();
  EXPECT_FALSE(bridge.wait_for("parameter I = ").empty()) << bridge.output();
  EXPECT_NE(bridge.output().find("standard input line 3: the firmware has no parameter named 'Q'"), std::string::npos)
      << bridge.output();
  EXPECT_FLOAT_EQ(csv.application.p, 0.05F);  // the lines after the long one still count
  EXPECT_FLOAT_EQ(csv.application.i, 0.01F);
  EXPECT_EQ(bridge.terminate(), 0) << bridge.output();
  EXPECT_NE(bridge.output().find("\"input_lines_rejected\":2"), std::string::npos) << bridge.output();
}

TEST(BridgeProgram, SetsGivenBeforeTheApplicationDescribedItselfWaitForIt) {
  auto arguments = bridge_command();
  if (!arguments) GTEST_SKIP() << "no DUET_BRIDGE_PROGRAM to run";
  PtyApplication application;
  application.start();
  arguments->insert(arguments->end(), {"--app-channel", "tty:" + application.path(), "--no-websocket", "--csv"});
  Child bridge{*arguments};
  bridge.write_line("D=0.02");  // at once, as from a file: before the description has come
  bridge.close_input();
  EXPECT_FALSE(bridge.wait_for("parameter D = ").empty()) << bridge.output();
  EXPECT_FLOAT_EQ(application.d, 0.02F);
  EXPECT_EQ(bridge.terminate(), 0) << bridge.output();
  EXPECT_NE(bridge.output().find("\"input_lines_rejected\":0"), std::string::npos) << bridge.output();
}

TEST(BridgeProgram, CsvThatCannotBeWrittenStopsTheBridgeWithAnError) {
  auto arguments = bridge_command();
  if (!arguments) GTEST_SKIP() << "no DUET_BRIDGE_PROGRAM to run";
  CsvBridge csv;
  ASSERT_NO_FATAL_FAILURE(start_csv_bridge(csv, *arguments));
  Child& bridge = *csv.bridge;
  bridge.close_output();  // the reader goes away; the next sample (at 100 Hz) cannot be written
  EXPECT_EQ(bridge.wait_for_exit(), 1) << bridge.output();
  EXPECT_NE(bridge.output().find("duet-bridge: CSV output on standard output: Broken pipe"), std::string::npos)
      << bridge.output();
  EXPECT_NE(bridge.output().find("duet-bridge: stopped; application channel"), std::string::npos) << bridge.output();
}

}  // namespace
}  // namespace duet::bridge
