// Processor in the loop, lock-step: the robot's firmware on QEMU's emulated Cortex-M4 (`duet pil`) balances the
// simulated robot for 10 s without an overrun, and the robot lives exactly the life it lives under the same generated
// code built for the PC (balbot_sil over the link to `duet plant serve`): every quantity of the robot, every
// millisecond, bit for bit, and the firmware's final tilt estimate and duty too. All programs run as a user runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "child_program.hpp"
#include "duet/mdf4/reader.hpp"
#include "duet/plot/csv.hpp"
#include "duet/support/text_file.hpp"
#include "recorded_daq_step.hpp"

namespace duet::sil {
namespace {

// Every line a program writes until it ends.
std::vector<std::string> all_lines(Program& program) {
  std::vector<std::string> lines;
  for (std::string line = program.line(); !line.empty(); line = program.line()) lines.push_back(line);
  return lines;
}

// The value of `key=` in a console line, as written.
std::string field(const std::string& line, const std::string& key) {
  const std::size_t at = line.find(" " + key + "=");
  if (at == std::string::npos) return {};
  const std::size_t start = at + key.size() + 2;
  return line.substr(start, line.find(' ', start) - start);
}

float float_from_bits(const std::string& hex) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(std::stoul(hex, nullptr, 16)));
}

TEST(BalbotPil, TenSecondsOnTheEmulatedCortexM4BalanceWithoutOverrunsAndMatchTheCodeOnThePc) {
  if (!std::filesystem::exists(BALBOT_PIL_FIRMWARE)) GTEST_SKIP() << "no firmware image " << BALBOT_PIL_FIRMWARE;
  const TemporaryFile pil_robot{"pil_robot.csv"};
  const TemporaryFile console{"pil_console.txt"};
  Program pil{DUET_PROGRAM,
              {"pil", BALBOT_PIL_FIRMWARE, "--scenario", DUET_BALBOT_SCENARIO, "--duration", "10", "--lock-step",
               "--no-bridge", "--csv", pil_robot.path(), "--console", console.path()},
              "pil"};
  ASSERT_TRUE(pil.started());
  const std::vector<std::string> summary = all_lines(pil);
  ASSERT_EQ(pil.wait(), 0) << pil.errors();

  // The firmware's own account: all 10001 ticks, no task ever late, the link held; and where the model ended.
  auto console_text = read_text_file(console.path());
  ASSERT_TRUE(console_text.ok()) << console_text.error();
  std::vector<std::string> ended;
  std::string signals;
  std::size_t task_lines = 0;
  std::size_t overrunning_tasks = 0;
  std::set<std::string> section_ceilings;
  for (std::size_t start = 0; start < console_text.value().size();) {
    const std::size_t end = console_text.value().find('\n', start);
    const std::string line = console_text.value().substr(start, end - start);
    start = end == std::string::npos ? console_text.value().size() : end + 1;
    if (line.starts_with("duet-end ")) ended.push_back(line);
    if (line.starts_with("balbot-signals ")) signals = line;
    if (line.starts_with("duet-task ")) {
      ++task_lines;
      if (field(line, "overruns") != "0") ++overrunning_tasks;
    }
    if (line.starts_with("duet-section ") && field(line, "longest_cycles") != "0")
      section_ceilings.insert(field(line, "ceiling"));
  }
  // Measured sections, blocking for duet sched: the executive's own at the ceiling of every task (TIM2's and TIM4's
  // group 1), and the settings that Linux's side and the model share at the ceiling of their users (rate 10, group 11,
  // and IPCC_RX1, group 9).
  EXPECT_EQ(section_ceilings, (std::set<std::string>{"1", "9"}));
  ASSERT_EQ(ended.size(), 1U) << console_text.value();
  EXPECT_EQ(ended[0], "duet-end reason=final_tick ticks=10001 overruns=0 link=ok");
  EXPECT_GE(task_lines, 11U * 10U);  // every task, every second
  EXPECT_EQ(overrunning_tasks, 0U);

  // The same generated code on the PC against the same robot, over the link.
  const TemporaryFile sil_robot{"sil_robot.csv"};
  Program server{DUET_PROGRAM,
                 {"plant", "serve", "balbot", "--scenario", DUET_BALBOT_SCENARIO, "--listen", "127.0.0.1:0", "--once",
                  "--csv", sil_robot.path()},
                 "server"};
  ASSERT_TRUE(server.started());
  const std::string address = listening_address(server);
  ASSERT_FALSE(address.empty());
  Program sil{BALBOT_SIL_PROGRAM, {"--link", address, "--duration", "10"}, "sil"};
  const std::string sil_summary = sil.line();
  ASSERT_EQ(sil.wait(), 0) << sil.errors();
  ASSERT_EQ(server.wait(), 0) << server.errors();

  // Back to back: the robot's every quantity at every tick, to the last bit (the CSVs write numbers that read back
  // as the same doubles), and the firmware's final tilt estimate.
  auto pil_text = read_text_file(pil_robot.path());
  auto sil_text = read_text_file(sil_robot.path());
  ASSERT_TRUE(pil_text.ok() && sil_text.ok());
  if (pil_text.value() != sil_text.value()) {
    const auto [differs, _] = std::mismatch(sil_text.value().begin(), sil_text.value().end(), pil_text.value().begin(),
                                            pil_text.value().end());
    FAIL() << "the robot's recordings differ from line " << std::count(sil_text.value().begin(), differs, '\n') + 1;
  }
  ASSERT_FALSE(signals.empty()) << console_text.value();
  const double pil_theta = float_from_bits(field(signals, "theta_bits"));
  EXPECT_TRUE(same_bits(pil_theta, number_after(sil_summary, "final theta "))) << signals << " / " << sil_summary;

  // Balanced: held at 5 degrees, let go at 2 s, within a degree from 4 s on (the robot's own tilt).
  auto robot = plot::read_csv(pil_text.value(), pil_robot.path());
  ASSERT_TRUE(robot.ok()) << robot.error();
  ASSERT_EQ(robot.value().time.size(), 10001U);
  const auto theta = std::find_if(robot.value().series.begin(), robot.value().series.end(),
                                  [](const plot::Series& series) { return series.name == "theta_deg"; });
  ASSERT_NE(theta, robot.value().series.end());
  EXPECT_EQ(theta->values.front(), 5.0);
  double largest = 0;
  for (std::size_t k = 4000; k < theta->values.size(); ++k) largest = std::max(largest, std::abs(theta->values[k]));
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(largest, 1.0);
}

// DAQ timestamps are the executive's time: the 1 ms task's samples, recorded over XCP through the bridge, advance by
// 1 ms on average to within 0.01 %, although the plant link sets its cycles aside at every exchange.
TEST(BalbotPil, DaqTimestampsOfTheMillisecondTaskAdvanceByItsPeriod) {
  if (!std::filesystem::exists(BALBOT_PIL_FIRMWARE)) GTEST_SKIP() << "no firmware image " << BALBOT_PIL_FIRMWARE;
  Program pil{DUET_PROGRAM,
              {"pil", BALBOT_PIL_FIRMWARE, "--scenario", DUET_BALBOT_SCENARIO, "--lock-step", "--xcp", "127.0.0.1:0",
               "--websocket", "127.0.0.1:0"},
              "pil_daq"};
  ASSERT_TRUE(pil.started());
  (void)pil.line();                    // what runs
  const std::string xcp = pil.line();  // "  XCP        tcp://127.0.0.1:PORT (A2L: FILE), e.g. ..."
  const std::size_t url = xcp.find("tcp://");
  ASSERT_NE(url, std::string::npos) << xcp;
  const double step = recorded_daq_step(DUET_BALBOT_A2L, xcp.substr(url, xcp.find(' ', url) - url));
  EXPECT_NEAR(step, 1e-3, 1e-7);
}

// The lines of `text` after the header, split by which of the recording's events they are a sample of: a CSV of
// `duet xcp record` on several events leaves the other events' fields empty. `first_columns` is the number of
// columns of the first event.
std::vector<std::vector<std::string>> csv_rows_by_event(const std::string& text, std::size_t first_columns) {
  std::vector<std::vector<std::string>> rows(2);
  std::size_t start = text.find('\n') + 1;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    const std::size_t after_time = line.find(',');
    rows[line.compare(after_time, first_columns + 1, std::string(first_columns + 1, ',')) == 0 ? 1 : 0].push_back(line);
  }
  return rows;
}

// The acceptance of `duet xcp record --mdf`: one recording of the firmware on QEMU, written as CSV and as MDF at
// once, two events (rate 1 and rate 10) with floats, booleans, a verbal state and a 32-bit counter. Every sample of
// the MDF file, its physical values printed as the CSV prints them, is the CSV's line for that sample.
TEST(BalbotPil, XcpRecordWritesToMdfTheValuesItWritesToCsv) {
  if (!std::filesystem::exists(BALBOT_PIL_FIRMWARE)) GTEST_SKIP() << "no firmware image " << BALBOT_PIL_FIRMWARE;
  Program pil{DUET_PROGRAM,
              {"pil", BALBOT_PIL_FIRMWARE, "--scenario", DUET_BALBOT_SCENARIO, "--lock-step", "--xcp", "127.0.0.1:0",
               "--websocket", "127.0.0.1:0"},
              "pil_mdf"};
  ASSERT_TRUE(pil.started());
  (void)pil.line();
  const std::string xcp = pil.line();
  const std::size_t url = xcp.find("tcp://");
  ASSERT_NE(url, std::string::npos) << xcp;
  const TemporaryFile csv{"record.csv"};
  const TemporaryFile mdf{"record.mf4"};
  const std::vector<std::string> fast{"theta", "stop", "robot_state", "requests_sent"};
  Program recorder{DUET_PROGRAM,
                   {"xcp",        "record",
                    "--a2l",      DUET_BALBOT_A2L,
                    "--connect",  xcp.substr(url, xcp.find(' ', url) - url),
                    "--signal",   "theta",
                    "--signal",   "stop",
                    "--signal",   "robot_state",
                    "--signal",   "requests_sent",
                    "--signal",   "y@rate 10",
                    "--signal",   "gains_from@rate 10",
                    "--event",    "rate 1",
                    "--duration", "10",
                    "--timeout",  "10000",
                    "--output",   csv.path(),
                    "--mdf",      mdf.path()},
                   "record_mdf"};
  ASSERT_EQ(recorder.wait(), 0) << recorder.errors();
  auto text = read_text_file(csv.path());
  ASSERT_TRUE(text.ok());
  const std::vector<std::vector<std::string>> rows = csv_rows_by_event(text.value(), fast.size());
  auto reader = mdf4::Reader::open(mdf.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  const mdf4::FileInfo& info = reader.value().info();
  ASSERT_EQ(info.groups.size(), 2U);
  EXPECT_EQ(info.groups[0].name, "rate 1");
  EXPECT_EQ(info.groups[1].name, "rate 10");
  EXPECT_EQ(info.groups[0].channels[2].bit_count, 8U);   // stop, UBYTE
  EXPECT_EQ(info.groups[0].channels[4].bit_count, 32U);  // requests_sent, ULONG
  for (std::size_t group = 0; group < 2; ++group) {
    std::size_t sample = 0;
    const Status read = reader.value().for_each_record(group, [&](const mdf4::Record& record) {
      std::ostringstream line;
      line << std::setprecision(9) << record.time();
      if (group == 1) line << std::string(fast.size(), ',');
      for (std::size_t channel = 1; channel < info.groups[group].channels.size(); ++channel) {
        const mdf4::Physical physical = record.physical(channel);
        line << ',' << std::setprecision(10)
             << (std::holds_alternative<double>(physical) ? std::get<double>(physical)
                                                          : mdf4::to_double(std::get<mdf4::Number>(physical)));
      }
      if (group == 0) line << ",,";
      ASSERT_LT(sample, rows[group].size());
      EXPECT_EQ(line.str(), rows[group][sample]) << "group " << group << ", sample " << sample;
      ++sample;
    });
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(sample, rows[group].size());
    EXPECT_GT(sample, group == 0 ? 500U : 50U);
  }
}

// The acceptance of `duet pil --signal`: one lock-step run of 10 s of model time writes one MDF file with the plant's
// truth (a row per tick) and the firmware's signals by XCP, a group per event, both on the simulation's time. The
// firmware tells the plant tick n (n ms) as the tick begins, before its executive counts it: the tasks of that tick
// run, and their DAQ samples are stamped, at (n + 1) ms and the few microseconds they start after the tick. So the
// rate 10 task, which runs in the ticks 0, 10, 20, ... as duet sim runs it, stamps 1 ms, 11 ms, 21 ms, ..., and the
// firmware's tilt estimate (theta, Kalman-filtered, deg) stamped t follows the plant's true tilt (theta_deg) of the
// row 1 ms before.
TEST(BalbotPil, PilRecordsThePlantsTruthAndTheFirmwaresSignalsInOneMdfFile) {
  if (!std::filesystem::exists(BALBOT_PIL_FIRMWARE)) GTEST_SKIP() << "no firmware image " << BALBOT_PIL_FIRMWARE;
  const TemporaryFile mdf{"pil_signals.mf4"};
  Program pil{DUET_PROGRAM,
              {"pil",
               BALBOT_PIL_FIRMWARE,
               "--scenario",
               DUET_BALBOT_SCENARIO,
               "--lock-step",
               "--duration",
               "10",
               "--xcp",
               "127.0.0.1:0",
               "--websocket",
               "127.0.0.1:0",
               "--mdf",
               mdf.path(),
               "--a2l",
               DUET_BALBOT_A2L,
               "--signal",
               "theta",
               "--signal",
               "y@rate 10",
               "--event",
               "rate 1"},
              "pil_signals"};
  ASSERT_TRUE(pil.started());
  const std::vector<std::string> lines = all_lines(pil);
  ASSERT_EQ(pil.wait(), 0) << pil.errors();
  const auto daq_line = std::find_if(lines.begin(), lines.end(),
                                     [](const std::string& line) { return line.starts_with("  daq       recorded "); });
  ASSERT_NE(daq_line, lines.end());
  EXPECT_NE(daq_line->find("(0 overloads, 0 lost packets, 0 discarded)"), std::string::npos) << *daq_line;

  auto reader = mdf4::Reader::open(mdf.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  const mdf4::FileInfo& info = reader.value().info();
  EXPECT_TRUE(info.finalised);
  ASSERT_EQ(info.groups.size(), 3U);
  EXPECT_EQ(info.groups[0].name, "every tick");
  EXPECT_EQ(info.groups[1].name, "rate 1");
  EXPECT_EQ(info.groups[2].name, "rate 10");
  EXPECT_EQ(info.groups[0].samples, 10001U);  // the ticks 0 to 10 s

  // The plant's true tilt by tick.
  std::size_t theta_deg = 0;
  for (std::size_t channel = 0; channel < info.groups[0].channels.size(); ++channel) {
    if (info.groups[0].channels[channel].name == "theta_deg") theta_deg = channel;
  }
  ASSERT_NE(theta_deg, 0U);
  std::vector<double> truth(10001, NAN);
  const auto tick_of = [](double time_s) { return static_cast<std::size_t>(std::llround(time_s * 1000)); };
  ASSERT_TRUE(reader.value()
                  .for_each_record(0,
                                   [&](const mdf4::Record& record) {
                                     const std::size_t tick = tick_of(record.time());
                                     if (tick < truth.size()) truth[tick] = mdf4::to_double(record.value(theta_deg));
                                   })
                  .ok());

  // Each event's samples, a period apart from DAQ's start to the run's end: none lost, none twice; 1 ms after the
  // ticks that ran them.
  for (const auto& [group, period_ms] : {std::pair{std::size_t{1}, 1U}, std::pair{std::size_t{2}, 10U}}) {
    std::vector<double> times;
    ASSERT_TRUE(reader.value()
                    .for_each_record(group, [&](const mdf4::Record& record) { times.push_back(record.time()); })
                    .ok());
    ASSERT_GT(times.size(), 100U) << "group " << group;
    EXPECT_GE(times.front(), 0.001);
    EXPECT_LT(times.back(), 10.0011);  // the last tick's, at 10 s, stamped 10.001 s and its task's start
    EXPECT_EQ(times.size(), (tick_of(times.back()) - tick_of(times.front())) / period_ms + 1)
        << "group " << group << " from " << times.front() << " s to " << times.back() << " s";
    for (double time_s : times) ASSERT_EQ(tick_of(time_s) % period_ms, 1U % period_ms) << time_s;
  }

  // The firmware's estimate against the truth, once the sensor is ready (1.5 s) and the filter has settled.
  double largest_difference = 0;
  double sum_of_differences = 0;
  std::size_t compared = 0;
  ASSERT_TRUE(reader.value()
                  .for_each_record(1,
                                   [&](const mdf4::Record& record) {
                                     const std::size_t tick = tick_of(record.time()) - 1;
                                     if (record.time() < 2.5 || tick >= truth.size()) return;
                                     const double difference = std::abs(mdf4::to_double(record.value(1)) - truth[tick]);
                                     largest_difference = std::max(largest_difference, difference);
                                     sum_of_differences += difference;
                                     ++compared;
                                   })
                  .ok());
  EXPECT_GT(compared, 7000U);
  EXPECT_LT(largest_difference, 1.0);                                  // 0.35 deg when written
  EXPECT_LT(sum_of_differences / static_cast<double>(compared), 0.2);  // 0.085 deg when written
}

}  // namespace
}  // namespace duet::sil
