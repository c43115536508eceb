// `duet pil` as a user types it: command lines it refuses, and runs against a stand-in for QEMU (pil_fake_qemu.cpp,
// DUET_FAKE_QEMU) that plays a firmware over the link: how a run ends, what the summary says, that the children
// are stopped and reaped and the temporary folder removed, whatever ends the run.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "duet/mdf4/reader.hpp"
#include "duet/plot/csv.hpp"
#include "duet/support/text_file.hpp"
#include "run_for_test.hpp"

namespace duet::cli {
namespace {

using namespace std::chrono_literals;

// A file in the system's temporary folder, removed at the end.
class TemporaryFile {
 public:
  TemporaryFile(const std::string& name, const std::string& text)
      : path_(std::filesystem::temp_directory_path() / ("duet_pil_" + std::to_string(::getpid()) + "_" + name)) {
    std::ofstream{path_} << text;
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() { std::filesystem::remove(path_); }
  [[nodiscard]] std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

const std::string balbot_a2l = DUET_SOURCE_DIR "/apps/balbot/generated/balbot.a2l";

TEST(PilCommand, BadCommandLinesSayWhatIsWrong) {
  const TemporaryFile firmware{"image.elf", ""};
  const auto usage_error = [](const std::vector<std::string>& arguments, const std::string& message) {
    const Outcome outcome = run(arguments);
    EXPECT_EQ(outcome.exit_code, ExitCode::usage) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, message)) << outcome.err;
    EXPECT_EQ(outcome.out, "");
  };
  usage_error({"pil"}, "firmware is required");
  usage_error({"pil", "/nonexistent/image.elf"}, "File does not exist: /nonexistent/image.elf");
  usage_error({"pil", firmware.path(), "--duration", "-1"}, "--duration: '-1' is not a positive number of seconds");
  usage_error({"pil", firmware.path(), "--duration", "0"}, "'0' is not a positive number of seconds");
  usage_error({"pil", firmware.path(), "--duration", "ten"}, "'ten' is not a positive number of seconds");
  usage_error({"pil", firmware.path(), "--xcp", "5555"}, "--xcp: '5555' is not HOST:PORT");
  usage_error({"pil", firmware.path(), "--websocket", "127.0.0.1:99999"}, "--websocket: ");
  usage_error({"pil", firmware.path(), "--xcp", "0.0.0.0:5555"}, "the bridge listens on 127.0.0.1 only");
  usage_error({"pil", firmware.path(), "--icount-shift", "11"}, "--icount-shift");
  usage_error({"pil", firmware.path(), "--no-bridge", "--bridge", "duet-bridge"}, "--no-bridge excludes --bridge");
  usage_error({"pil", firmware.path(), "--seed", "many"}, "--seed");
  // The firmware's signals go into the MDF file, by XCP through the bridge, named by the A2L.
  usage_error({"pil", firmware.path(), "--signal", "theta", "--a2l", balbot_a2l}, "--signal requires --mdf");
  usage_error({"pil", firmware.path(), "--signal", "theta", "--mdf", "run.mf4"}, "--signal requires --a2l");
  usage_error({"pil", firmware.path(), "--signal", "theta", "--mdf", "run.mf4", "--a2l", balbot_a2l, "--no-bridge"},
              "--no-bridge excludes --signal");
  usage_error({"pil", firmware.path(), "--event", "rate 1"}, "--event requires --signal");
  usage_error({"pil", firmware.path(), "--signal", "theta", "--mdf", "run.mf4", "--a2l", "/nonexistent/a.a2l"},
              "File does not exist: /nonexistent/a.a2l");
}

TEST(PilCommand, FirmwareSignalsTheA2lDoesNotHaveAreRefusedBeforeTheRun) {
  const TemporaryFile firmware{"image.elf", ""};
  const TemporaryFile mdf{"refused.mf4", ""};
  const auto refused = [&](const std::vector<std::string>& signal, const std::string& message) {
    std::vector<std::string> arguments{"pil",   firmware.path(), "--qemu", DUET_FAKE_QEMU,
                                       "--mdf", mdf.path(),      "--a2l",  balbot_a2l};
    arguments.insert(arguments.end(), signal.begin(), signal.end());
    const Outcome outcome = run(arguments);
    EXPECT_EQ(outcome.exit_code, ExitCode::failure);
    EXPECT_EQ(outcome.err, "duet pil: " + message + "\n");
    EXPECT_EQ(outcome.out, "");  // nothing ran
  };
  refused({"--signal", "thetta@rate 1"}, "'thetta' is neither a MEASUREMENT nor a CHARACTERISTIC in the A2L");
  refused({"--signal", "theta@rate 3"}, "'rate 3' is no event in the A2L (give its name or number)");
  refused({"--signal", "theta"}, "--signal 'theta': give NAME@EVENT, or --event for all");
  refused({"--signal", "theta", "--event", "fast"}, "'fast' is no event in the A2L (give its name or number)");
}

// A firmware that never answers XCP (the stand-in for QEMU has no XCP slave): the run fails and says so, and the
// MDF file holds the plant's rows, finalised, and the event's group without samples.
TEST(PilCommand, AFirmwareThatDoesNotAnswerXcpFailsTheRunAndKeepsThePlantsRows) {
  const TemporaryFile firmware{"image.elf", ""};
  const TemporaryFile mdf{"silent.mf4", ""};
  const Outcome outcome =
      run({"pil",   firmware.path(), "--qemu",      DUET_FAKE_QEMU, "--bridge",    DUET_BRIDGE_PROGRAM,
           "--xcp", "127.0.0.1:0",   "--websocket", "127.0.0.1:0",  "--lock-step", "--duration",
           "0.3",   "--mdf",         mdf.path(),    "--a2l",        balbot_a2l,    "--signal",
           "theta", "--signal",      "y@rate 10",   "--event",      "rate 1"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_TRUE(contains(outcome.err,
                       "duet pil: recording the firmware's signals: the run ended before the firmware answered XCP on "
                       "tcp://127.0.0.1:"))
      << outcome.err;
  EXPECT_TRUE(contains(outcome.out,
                       "  daq       recorded 0 samples of 1 signals on event 'rate 1', 0 samples of 1 signals on "
                       "event 'rate 10'\n"))
      << outcome.out;
  auto reader = mdf4::Reader::open(mdf.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  const mdf4::FileInfo& info = reader.value().info();
  EXPECT_TRUE(info.finalised);
  ASSERT_EQ(info.groups.size(), 3U);
  EXPECT_EQ(info.groups[0].name, "every tick");
  EXPECT_EQ(info.groups[0].samples, 300U);
  EXPECT_EQ(info.groups[1].name, "rate 1");
  EXPECT_EQ(info.groups[1].channels[1].name, "theta");
  EXPECT_EQ(info.groups[1].samples, 0U);
  EXPECT_EQ(info.groups[2].name, "rate 10");
  EXPECT_EQ(info.groups[2].samples, 0U);
}

TEST(PilCommand, APlantThatCannotBeMadeOrFilesThatCannotBeWritten) {
  const TemporaryFile firmware{"image.elf", ""};
  const Outcome scenario_for_none = run({"pil", firmware.path(), "--plant", "none", "--scenario", "robot.yaml"});
  EXPECT_EQ(scenario_for_none.exit_code, ExitCode::failure);
  EXPECT_EQ(scenario_for_none.err, "duet pil: --scenario is for the balbot plant; plant 'none' takes none\n");

  const Outcome unknown = run({"pil", firmware.path(), "--plant", "nonee"});
  EXPECT_EQ(unknown.exit_code, ExitCode::failure);
  EXPECT_EQ(unknown.err, "duet pil: unknown plant 'nonee' (did you mean 'none'?)\n");

  const Outcome missing_scenario = run({"pil", firmware.path(), "--scenario", "/nonexistent/robot.yaml"});
  EXPECT_EQ(missing_scenario.exit_code, ExitCode::failure);
  EXPECT_TRUE(contains(missing_scenario.err, "/nonexistent/robot.yaml")) << missing_scenario.err;

  for (const char* option : {"--csv", "--plot", "--mdf", "--console"}) {
    const Outcome unwritable = run({"pil", firmware.path(), option, "/nonexistent/file"});
    EXPECT_EQ(unwritable.exit_code, ExitCode::failure);
    EXPECT_EQ(unwritable.err, "duet pil: cannot write /nonexistent/file\n") << option;
  }
}

TEST(PilCommand, AnEmulatorThatCannotRun) {
  const TemporaryFile firmware{"image.elf", ""};
  const Outcome outcome = run({"pil", firmware.path(), "--qemu", "/nonexistent/qemu-system-arm", "--no-bridge"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_TRUE(contains(outcome.err, "duet pil: cannot run /nonexistent/qemu-system-arm: No such file or directory"))
      << outcome.err;
}

TEST(PilCommand, ABridgeThatCannotRun) {
  const TemporaryFile firmware{"image.elf", ""};
  const Outcome outcome =
      run({"pil", firmware.path(), "--qemu", DUET_FAKE_QEMU, "--bridge", "/nonexistent/duet-bridge"});
  EXPECT_EQ(outcome.exit_code, ExitCode::failure);
  EXPECT_TRUE(contains(outcome.err, "cannot run /nonexistent/duet-bridge: No such file or directory")) << outcome.err;
}

// The temporary folder the run printed (with --no-bridge: "...channel is unix:FOLDER/xcp.sock, ...").
std::filesystem::path run_folder(const std::string& out) {
  const std::size_t start = out.find("unix:");
  const std::size_t end = out.find("/xcp.sock");
  if (start == std::string::npos || end == std::string::npos) return {};
  return out.substr(start + 5, end - start - 5);
}

TEST(PilCommand, ALockStepRunThatEndsByItself) {
  const TemporaryFile firmware{"image.elf", ""};
  const TemporaryFile csv{"plant.csv", ""};
  const TemporaryFile mdf{"plant.mf4", ""};
  const TemporaryFile console{"console.txt", ""};
  const TemporaryFile scenario{"robot.yaml", "initial_tilt_deg: 2\nrelease_time_s: 0.2\nnoise: false\n"};
  const Outcome outcome =
      run({"pil", firmware.path(), "--qemu", DUET_FAKE_QEMU, "--no-bridge", "--lock-step", "--duration", "0.5",
           "--scenario", scenario.path(), "--csv", csv.path(), "--mdf", mdf.path(), "--console", console.path()});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  EXPECT_TRUE(contains(outcome.out, ", plant balbot, lock-step\n")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "Ctrl-C ends the run (else it ends after 0.5 s of model time)")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "duet pil: the firmware ended (final_tick) with exit code 0\n")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "  run       0.500 s of model time in ")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "  tilt      whole run: mean ")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "            from the release at 0.200 s: mean ")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "  link      500 ticks, ")) << outcome.out;  // and the robot's interrupts
  EXPECT_TRUE(contains(outcome.out, "  firmware  500 ticks, 0 overruns, core load 25.00 %; ended: final_tick\n"))
      << outcome.out;
  // 150 and 200 cycles of 40 ns at 4 ns an instruction (shift 2): 1500 and 2000 instructions, 2000 / 209 us.
  EXPECT_TRUE(contains(outcome.out, "step_rate_1         500         0        1500       2000           9.57\n"))
      << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "  xcp       no bridge (--no-bridge)\n")) << outcome.out;
  const std::filesystem::path folder = run_folder(outcome.out);
  EXPECT_FALSE(folder.empty()) << outcome.out;
  EXPECT_FALSE(std::filesystem::exists(folder)) << folder;

  auto recorded = plot::read_csv(read_text_file(csv.path()).value(), csv.path());
  ASSERT_TRUE(recorded.ok()) << recorded.error();
  ASSERT_EQ(recorded.value().time.size(), 500U);  // a row per tick
  EXPECT_EQ(recorded.value().time.back(), 0.5);
  // The MDF file: one group of the same quantities, as doubles, the same values.
  auto reader = mdf4::Reader::open(mdf.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  ASSERT_EQ(reader.value().info().groups.size(), 1U);
  const mdf4::GroupInfo& group = reader.value().info().groups[0];
  EXPECT_EQ(group.name, "every tick");
  EXPECT_EQ(group.samples, 500U);
  ASSERT_EQ(group.channels.size(), recorded.value().series.size() + 1);
  std::size_t row = 0;
  const Status read = reader.value().for_each_record(0, [&](const mdf4::Record& record) {
    EXPECT_EQ(record.time(), recorded.value().time[row]);
    for (std::size_t column = 0; column < recorded.value().series.size(); ++column) {
      EXPECT_EQ(group.channels[column + 1].name, recorded.value().series[column].name);
      EXPECT_EQ(group.channels[column + 1].bit_count, 64U);
      EXPECT_EQ(mdf4::to_double(record.value(column + 1)), recorded.value().series[column].values[row]);
    }
    ++row;
  });
  EXPECT_TRUE(read.ok()) << read.error();
  auto lines = read_text_file(console.path());
  ASSERT_TRUE(lines.ok());
  EXPECT_TRUE(lines.value().starts_with("fake-qemu pid=")) << lines.value();
  EXPECT_TRUE(lines.value().ends_with("duet-end reason=final_tick ticks=500 overruns=0\n")) << lines.value();
}

// An imported FMU as the plant (issue #25): initialised when the firmware's HELLO gives the base period, stepped a
// tick after a tick, recorded, and its request to stop ends the run at that tick, which is no failure.
TEST(PilCommand, AnFmuAsThePlantStepsWithTheFirmwareAndEndsTheRunWhenItAsksTo) {
  const TemporaryFile firmware{"image.elf", ""};
  const TemporaryFile csv{"fmu.csv", ""};
  const TemporaryFile mapping{"stop.yaml",
                              "outputs:\n  - {variable: y, resource: \"adc:ADC1/6\"}\nset:\n  stop_at: 0.05\n"};
  const std::string fmu = std::string{DUET_TEST_FMU_DIR} + "/Terminating_fmi2.fmu";
  const Outcome outcome = run({"pil", firmware.path(), "--qemu", DUET_FAKE_QEMU, "--no-bridge", "--lock-step",
                               "--duration", "0.5", "--plant", fmu, "--connect", mapping.path(), "--csv", csv.path()});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err << outcome.out;
  EXPECT_TRUE(contains(outcome.out, ", plant " + fmu + ", lock-step\n")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out,
                       "duet pil: the plant asked to stop at t = 0.05 s: Terminating asked to stop at "
                       "t = 0.05 s\n"))
      << outcome.out;
  auto recorded = plot::read_csv(read_text_file(csv.path()).value(), csv.path());
  ASSERT_TRUE(recorded.ok()) << recorded.error();
  ASSERT_EQ(recorded.value().series.size(), 1U);
  EXPECT_EQ(recorded.value().series[0].name, "y");
  ASSERT_EQ(recorded.value().time.size(), 50U);  // ticks 1 to 50 ms, the last the one that asked
  for (std::size_t row = 0; row < recorded.value().time.size(); ++row)
    EXPECT_NEAR(recorded.value().series[0].values[row], recorded.value().time[row], 1e-12) << row;  // y = time

  const Outcome unmapped = run({"pil", firmware.path(), "--qemu", DUET_FAKE_QEMU, "--plant", fmu});
  EXPECT_EQ(unmapped.exit_code, ExitCode::usage);
  EXPECT_EQ(unmapped.err, "duet pil: an FMU as the plant needs --connect MAPPING.yaml\n");
}

TEST(PilCommand, RealTimeTakesTheRunsDuration) {
  const TemporaryFile firmware{"image.elf", ""};
  const auto start = std::chrono::steady_clock::now();
  const Outcome outcome =
      run({"pil", firmware.path(), "--qemu", DUET_FAKE_QEMU, "--no-bridge", "--plant", "none", "--duration", "0.3"});
  EXPECT_GE(std::chrono::steady_clock::now() - start, 300ms);
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  EXPECT_TRUE(contains(outcome.out, ", plant none, real time\n")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, " x real time (real time)\n  pacing    the run ended within its first second"))
      << outcome.out;
  EXPECT_FALSE(contains(outcome.out, "tilt")) << outcome.out;  // the plant none has no tilt
}

TEST(PilCommand, AFirmwareThatFailsFailsTheRun) {
  const TemporaryFile failing{"failing.elf", "exit_code=3\n"};
  const Outcome failed =
      run({"pil", failing.path(), "--qemu", DUET_FAKE_QEMU, "--no-bridge", "--lock-step", "--duration", "0.1"});
  EXPECT_EQ(failed.exit_code, ExitCode::failure);
  EXPECT_EQ(failed.err, "duet pil: the firmware failed: exit code 3\n");
  EXPECT_TRUE(contains(failed.out, "summary\n")) << failed.out;

  const TemporaryFile unconnected{"unconnected.elf", "connect=0\nexit_code=1\n"};
  const Outcome never = run({"pil", unconnected.path(), "--qemu", DUET_FAKE_QEMU, "--no-bridge"});
  EXPECT_EQ(never.exit_code, ExitCode::failure);
  EXPECT_EQ(never.err, "duet pil: QEMU ended with exit code 1 before the firmware connected to the plant\n");

  const TemporaryFile garbage{"garbage.elf", "garbage=1\n"};
  const Outcome broken = run({"pil", garbage.path(), "--qemu", DUET_FAKE_QEMU, "--no-bridge", "--lock-step"});
  EXPECT_EQ(broken.exit_code, ExitCode::failure);
  EXPECT_EQ(broken.err,
            "duet pil: the plant session failed: the firmware sent a bad frame (unknown frame kind 0x42) while "
            "awaiting WRITE, READ, TICK or BYE\n");
}

TEST(PilCommand, TheBridgeRelaysAndReportsItsCounters) {
  const TemporaryFile firmware{"image.elf", ""};
  const Outcome outcome =
      run({"pil", firmware.path(), "--qemu", DUET_FAKE_QEMU, "--bridge", DUET_BRIDGE_PROGRAM, "--xcp", "127.0.0.1:0",
           "--websocket", "127.0.0.1:0", "--lock-step", "--duration", "0.2"});
  EXPECT_EQ(outcome.exit_code, ExitCode::success) << outcome.err;
  // Where the bridge listens, with the ports it took for port 0.
  EXPECT_TRUE(contains(outcome.out, "  XCP        tcp://127.0.0.1:")) << outcome.out;
  EXPECT_FALSE(contains(outcome.out, "tcp://127.0.0.1:0 ")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, " (A2L: apps/balbot/generated/balbot.a2l)")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out, "  dashboard  http://127.0.0.1:")) << outcome.out;
  EXPECT_FALSE(contains(outcome.out, "http://127.0.0.1:0/")) << outcome.out;
  EXPECT_TRUE(contains(outcome.out,
                       "  xcp       0 frames to the slave (0 bytes), 0 to the master (0 bytes), 0 DAQ frames dropped, "
                       "0 masters served\n"))
      << outcome.out;
}

// Whether process `pid` is gone (or a zombie nobody reaps: dead all the same).
bool gone(pid_t pid) {
  auto status = read_text_file("/proc/" + std::to_string(pid) + "/stat");
  if (!status) return true;
  const std::size_t name_end = status.value().rfind(')');
  return name_end != std::string::npos && status.value().substr(name_end + 2, 1) == "Z";
}

// The fake QEMU's pid, from the console file, once it said it.
pid_t fake_qemu_pid(const std::string& console) {
  for (int attempt = 0; attempt < 200; ++attempt) {
    auto text = read_text_file(console);
    const std::string said = "fake-qemu pid=";
    if (text && text.value().starts_with(said) && contains(text.value(), "\n")) {
      return static_cast<pid_t>(std::stol(text.value().substr(said.size())));
    }
    std::this_thread::sleep_for(50ms);
  }
  return -1;
}

// The program itself, as a child, for what a signal does to it.
ChildProcess start_duet(const std::vector<std::string>& arguments) {
  std::vector<std::string> command{DUET_PROGRAM};
  command.insert(command.end(), arguments.begin(), arguments.end());
  auto started = ChildProcess::start(command, {ChildProcess::Output::pipe, ChildProcess::Output::pipe});
  EXPECT_TRUE(started.ok()) << started.error();
  return std::move(started).value();
}

std::string everything(int fd) {
  std::string text;
  char bytes[4096];
  for (ssize_t got = 0; (got = ::read(fd, bytes, sizeof bytes)) > 0;) text.append(bytes, static_cast<std::size_t>(got));
  return text;
}

// The stop may cut the firmware's console in the middle of a line: that is no malformed report.
TEST(PilCommand, CtrlCEndsAHealthyRunInOrder) {
  const TemporaryFile firmware{"image.elf", "cut_line=1\n"};
  const TemporaryFile console{"signal_console.txt", ""};
  ChildProcess duet = start_duet({"pil", firmware.path(), "--qemu", DUET_FAKE_QEMU, "--bridge", DUET_BRIDGE_PROGRAM,
                                  "--xcp", "127.0.0.1:0", "--websocket", "127.0.0.1:0", "--console", console.path()});
  const pid_t qemu = fake_qemu_pid(console.path());
  ASSERT_GT(qemu, 0);
  std::this_thread::sleep_for(300ms);
  duet.signal(SIGINT);
  EXPECT_EQ(duet.stop(10s, 0), 0);  // signal 0: only waits
  const std::string out = everything(duet.output_fd());
  EXPECT_TRUE(contains(out, "duet pil: stopped by a signal\n")) << out;
  EXPECT_TRUE(contains(out, "  link      ")) << out;  // what the session got to, though the stop cut it
  EXPECT_FALSE(contains(out, "  link      0 ticks")) << out;
  EXPECT_TRUE(contains(out, "  xcp       0 frames to the slave")) << out;
  EXPECT_EQ(everything(duet.errors_fd()), "");
  EXPECT_TRUE(contains(read_text_file(console.path()).value(), "duet-task i\n"))
      << read_text_file(console.path()).value();
  EXPECT_TRUE(gone(qemu));
}

TEST(PilCommand, NothingOutlivesAKilledDuet) {
  const TemporaryFile firmware{"image.elf", "hang=1\n"};  // an emulator that would wait forever
  const TemporaryFile console{"kill_console.txt", ""};
  ChildProcess duet =
      start_duet({"pil", firmware.path(), "--qemu", DUET_FAKE_QEMU, "--no-bridge", "--console", console.path()});
  const pid_t qemu = fake_qemu_pid(console.path());
  ASSERT_GT(qemu, 0);
  duet.stop(0ms, SIGKILL);
  std::filesystem::remove_all(run_folder(everything(duet.output_fd())));  // the one thing a killed duet leaves
  bool ended = false;
  for (int attempt = 0; attempt < 100 && !ended; ++attempt) {
    ended = gone(qemu);
    std::this_thread::sleep_for(20ms);
  }
  EXPECT_TRUE(ended) << "the emulator " << qemu << " outlived duet";
}

}  // namespace
}  // namespace duet::cli
