// `duet xcp` against a slave running in this process (TestTarget), as a user would type it.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <signal.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "duet/mdf4/reader.hpp"
#include "duet/plot/csv.hpp"
#include "duet/support/text_file.hpp"
#include "run_for_test.hpp"
#include "scripted_slave.hpp"
#include "test_target.hpp"

namespace duet::cli {
namespace {

using namespace duet::xcp::host;

// The target's model, a step every 0.5 ms (the 1 ms event each step, the 10 ms event every second) until stopped.
class SteppingModel {
 public:
  explicit SteppingModel(TestTarget& target)
      : thread_{[this, &target] {
          for (std::uint32_t number = 1; running_; ++number) {
            target.step(number);
            std::this_thread::sleep_for(std::chrono::microseconds{500});
          }
        }} {}
  SteppingModel(const SteppingModel&) = delete;
  SteppingModel& operator=(const SteppingModel&) = delete;
  ~SteppingModel() { stop(); }
  void stop() {
    running_ = false;
    if (thread_.joinable()) thread_.join();
  }

 private:
  std::atomic<bool> running_{true};
  std::thread thread_;
};

class XcpCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(target.server.start({}).ok());
    endpoint = "tcp://127.0.0.1:" + std::to_string(target.server.port());
    a2l_file =
        (std::filesystem::temp_directory_path() / ("duet_xcp_command_" + std::to_string(::getpid()) + ".a2l")).string();
    std::ofstream{a2l_file} << write_a2l(TestTarget::a2l({Protocol::tcp, "127.0.0.1", target.server.port()}));
  }
  void TearDown() override { std::filesystem::remove(a2l_file); }

  TestTarget target{0};  // nothing locked
  std::string endpoint;
  std::string a2l_file;
};

TEST_F(XcpCommand, InfoShowsTheSlave) {
  const Outcome text = run({"xcp", "info", "--connect", endpoint});
  EXPECT_EQ(text.exit_code, ExitCode::success) << text.err;
  EXPECT_NE(text.out.find("slave        duet_target\nMAX_CTO      32\nMAX_DTO      64\n"), std::string::npos)
      << text.out;
  const Outcome json = run({"xcp", "info", "--a2l", a2l_file, "--json"});  // the A2L says where the slave is
  ASSERT_EQ(json.exit_code, ExitCode::success) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["max_dto"], 64);
}

// Another firmware's A2L would put reads and writes at the wrong addresses: its EPK differs, and no command runs.
TEST_F(XcpCommand, AnA2lOfAnotherFirmwareIsRefusedAtConnect) {
  A2lDescription other = TestTarget::a2l({Protocol::tcp, "127.0.0.1", target.server.port()});
  other.epk = "duet_target 2";
  std::ofstream{a2l_file} << write_a2l(other);
  const Outcome write = run({"xcp", "write", "--a2l", a2l_file, "gain=2"});
  EXPECT_EQ(write.exit_code, ExitCode::failure);
  EXPECT_NE(write.err.find("the slave holds EPK \"duet_target 1\" at 0x4000, the A2L names \"duet_target 2\""),
            std::string::npos)
      << write.err;
  EXPECT_EQ(target.parameters[0], 0);  // nothing written
}

// What the reader leaves out of another tool's A2L is said, not dropped in silence.
TEST_F(XcpCommand, WhatTheA2lReaderLeavesOutIsSaid) {
  std::string text = write_a2l(TestTarget::a2l({Protocol::tcp, "127.0.0.1", target.server.port()}));
  text.insert(text.find("  /end MODULE"), "    /begin BLOB recording \"a blob\" 0x1000 4 /end BLOB\n");
  std::ofstream{a2l_file} << text;
  const Outcome list = run({"xcp", "list", "--a2l", a2l_file});
  EXPECT_EQ(list.exit_code, ExitCode::success) << list.err;
  EXPECT_NE(list.err.find("duet xcp: warning: " + a2l_file + ":"), std::string::npos) << list.err;
  EXPECT_NE(list.err.find(": BLOB is not read\n"), std::string::npos) << list.err;
}

TEST_F(XcpCommand, ListsTheA2l) {
  const Outcome list = run({"xcp", "list", "--a2l", a2l_file, "--json"});
  ASSERT_EQ(list.exit_code, ExitCode::success) << list.err;
  const nlohmann::json entries = nlohmann::json::parse(list.out);
  ASSERT_EQ(entries.size(), 6U);
  EXPECT_EQ(entries[0]["name"], "counter");
  EXPECT_EQ(entries[4]["unit"], "V");
  const Outcome text = run({"xcp", "list", "--a2l", a2l_file});
  EXPECT_NE(text.out.find("scaled                  characteristic UWORD        0x00002004  a scaled word"),
            std::string::npos)
      << text.out;
}

TEST_F(XcpCommand, WritesAndReadsByNameWithinLimits) {
  Outcome written = run({"xcp", "write", "--a2l", a2l_file, "gain=2.5", "scaled=7.5", "flags=9"});
  ASSERT_EQ(written.exit_code, ExitCode::success) << written.err;
  EXPECT_EQ(target.parameters, (std::array<std::uint8_t, 8>{0x00, 0x00, 0x20, 0x40, 0xEE, 0x02, 9, 9}));
  const Outcome read = run({"xcp", "read", "--a2l", a2l_file, "--json", "gain", "scaled", "flags", "0x2000:2"});
  ASSERT_EQ(read.exit_code, ExitCode::success) << read.err;
  const nlohmann::json values = nlohmann::json::parse(read.out);
  EXPECT_EQ(values["gain"], 2.5);
  EXPECT_DOUBLE_EQ(values["scaled"].get<double>(), 7.5);
  EXPECT_EQ(values["flags"], nlohmann::json::array({9, 9}));
  EXPECT_EQ(values["0x2000:2"], "00 00");

  const Outcome too_big = run({"xcp", "write", "--a2l", a2l_file, "scaled=11"});
  EXPECT_EQ(too_big.exit_code, ExitCode::failure);
  EXPECT_EQ(too_big.err, "duet xcp: scaled: 11 is outside 0 .. 10 V\n");
  const Outcome unknown = run({"xcp", "read", "--a2l", a2l_file, "nothing"});
  EXPECT_EQ(unknown.exit_code, ExitCode::failure);
  EXPECT_EQ(unknown.err, "duet xcp: 'nothing' is neither a MEASUREMENT nor a CHARACTERISTIC in the A2L\n");
  const Outcome denied = run({"xcp", "read", "--connect", endpoint, "0x9000:4"});
  EXPECT_EQ(denied.err, "duet xcp: UPLOAD: ERR_ACCESS_DENIED (0x24)\n");
}

TEST_F(XcpCommand, RecordsSignalsToCsv) {
  SteppingModel model{target};
  const std::string csv_file = a2l_file + ".csv";
  const Outcome recorded = run({"xcp", "record", "--a2l", a2l_file, "--signal", "counter", "--signal", "twice",
                                "--event", "1 ms", "--duration", "0.3", "--output", csv_file});
  model.stop();
  ASSERT_EQ(recorded.exit_code, ExitCode::success) << recorded.err;
  std::ifstream csv{csv_file};
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "time_s,counter,twice");
  std::size_t rows = 0;
  std::string row;
  while (std::getline(csv, row)) {
    const std::size_t first = row.find(',');
    const std::size_t second = row.find(',', first + 1);
    const double counter = std::stod(row.substr(first + 1, second - first - 1));
    EXPECT_EQ(std::stod(row.substr(second + 1)), 2 * counter) << row;
    ++rows;
  }
  std::filesystem::remove(csv_file);
  EXPECT_GT(rows, 50U);
  EXPECT_NE(recorded.err.find("recorded " + std::to_string(rows) +
                              " samples of 2 signals on event '1 ms' (0 overloads, 0 lost"),
            std::string::npos)
      << recorded.err;
  EXPECT_FALSE(target.slave.connected());  // the command disconnected when done
}

// --mdf beside --output: a group per event (signals on "1 ms" by --event, `slow` by NAME@EVENT on "10 ms"), each
// signal in its A2L type with its unit, description and conversion, the same samples and times as the CSV.
TEST_F(XcpCommand, RecordsSeveralEventsToMdfAndCsv) {
  SteppingModel model{target};
  const std::string csv_file = a2l_file + ".csv";
  const std::string mdf_file = a2l_file + ".mf4";
  const Outcome recorded =
      run({"xcp",        "record", "--a2l",    a2l_file, "--signal", "counter", "--signal", "slow@10 ms",
           "--signal",   "twice",  "--signal", "scaled", "--signal", "flags",   "--event",  "1 ms",
           "--duration", "0.3",    "--output", csv_file, "--mdf",    mdf_file});
  model.stop();
  ASSERT_EQ(recorded.exit_code, ExitCode::success) << recorded.err;
  EXPECT_NE(recorded.err.find(" samples of 4 signals on event '1 ms', "), std::string::npos) << recorded.err;
  EXPECT_NE(recorded.err.find(" samples of 1 signals on event '10 ms' (0 overloads"), std::string::npos)
      << recorded.err;
  auto reader = mdf4::Reader::open(mdf_file);
  ASSERT_TRUE(reader.ok()) << reader.error();
  const mdf4::FileInfo& info = reader.value().info();
  EXPECT_TRUE(info.finalised);
  ASSERT_EQ(info.groups.size(), 2U);
  EXPECT_EQ(info.groups[0].name, "1 ms");
  EXPECT_EQ(info.groups[1].name, "10 ms");
  const auto& fast = info.groups[0].channels;
  ASSERT_EQ(fast.size(), 6U);  // time, counter, twice, scaled, flags[0], flags[1]
  EXPECT_EQ(fast[1].name, "counter");
  EXPECT_EQ(fast[1].comment, "step number");
  EXPECT_EQ(fast[1].bit_count, 32U);
  EXPECT_EQ(fast[2].bit_count, 16U);
  EXPECT_EQ(fast[3].unit, "V");
  EXPECT_EQ(fast[3].conversion.kind, mdf4::Conversion::Kind::linear);
  EXPECT_EQ(fast[3].conversion.factor, 0.01);
  EXPECT_EQ(fast[4].name, "flags[0]");
  EXPECT_EQ(fast[4].comment, "two bytes (raw values, named by the A2L: 0 clear, 1 set)");
  EXPECT_EQ(info.groups[1].channels[1].name, "slow");
  EXPECT_EQ(info.groups[1].channels[1].bit_count, 8U);

  // The CSV: a row per sample of either event, the other event's fields empty; the MDF's groups in the same order.
  auto csv = plot::read_csv(read_text_file(csv_file).value(), csv_file);
  ASSERT_TRUE(csv.ok()) << csv.error();
  ASSERT_EQ(csv.value().series.size(), 6U);
  EXPECT_EQ(csv.value().series[4].name, "flags[1]");
  EXPECT_EQ(csv.value().series[5].name, "slow");
  std::vector<std::vector<std::size_t>> rows(2);
  for (std::size_t row = 0; row < csv.value().time.size(); ++row)
    rows[std::isnan(csv.value().series[0].values[row]) ? 1 : 0].push_back(row);
  for (std::size_t group = 0; group < 2; ++group) {
    std::size_t sample = 0;
    const Status read = reader.value().for_each_record(group, [&](const mdf4::Record& record) {
      ASSERT_LT(sample, rows[group].size());
      const std::size_t row = rows[group][sample++];
      EXPECT_NEAR(record.time(), csv.value().time[row], 1e-9);
      const std::size_t first = group == 0 ? 0 : 5;
      for (std::size_t channel = 1; channel < info.groups[group].channels.size(); ++channel) {
        const mdf4::Physical physical = record.physical(channel);
        const double value = std::holds_alternative<double>(physical)
                                 ? std::get<double>(physical)
                                 : mdf4::to_double(std::get<mdf4::Number>(physical));
        EXPECT_EQ(value, csv.value().series[first + channel - 1].values[row]) << "row " << row;
      }
    });
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(sample, rows[group].size());
    EXPECT_GT(sample, group == 0 ? 50U : 10U);
  }
  std::filesystem::remove(csv_file);
  std::filesystem::remove(mdf_file);
}

// Ctrl-C (SIGINT) ends a recording early as a user wants it ended: the MDF file finalised with what came.
TEST_F(XcpCommand, RecordingStoppedBySigintLeavesAFinalisedMdfFile) {
  const std::string mdf_file = a2l_file + ".stopped.mf4";
  SteppingModel model{target};
  std::thread interrupt{[&] {
    // The flush after the first second shows the recording (and so its signal handler) running.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds{20};
    while (std::chrono::steady_clock::now() < deadline &&
           (!std::filesystem::exists(mdf_file) || std::filesystem::file_size(mdf_file) < 4096)) {
      std::this_thread::sleep_for(std::chrono::milliseconds{20});
    }
    ::kill(::getpid(), SIGINT);
  }};
  const Outcome recorded = run({"xcp", "record", "--a2l", a2l_file, "--signal", "counter", "--event", "1 ms",
                                "--duration", "60", "--mdf", mdf_file});
  interrupt.join();
  model.stop();
  EXPECT_EQ(recorded.exit_code, ExitCode::success) << recorded.err;
  EXPECT_NE(recorded.err.find("duet xcp: stopped by a signal; the files hold what came until then\n"),
            std::string::npos)
      << recorded.err;
  EXPECT_EQ(recorded.out, "");  // with --mdf and no --output, no CSV
  auto reader = mdf4::Reader::open(mdf_file);
  ASSERT_TRUE(reader.ok()) << reader.error();
  EXPECT_TRUE(reader.value().info().finalised);
  EXPECT_GT(reader.value().info().groups[0].samples, 500U);
  std::filesystem::remove(mdf_file);
}

// One session records and tunes: the bridge, like XCP, serves one master, so a second `duet xcp write` would be
// refused while the recording runs.
TEST_F(XcpCommand, RecordsWhileWritingATimedParameterAndPlots) {
  SteppingModel model{target};
  const std::string csv_file = a2l_file + ".csv";
  const std::string svg_file = a2l_file + ".svg";
  const Outcome recorded = run({"xcp", "record", "--a2l", a2l_file, "--signal", "counter", "--signal", "gain",
                                "--event", "1 ms", "--duration", "0.4", "--write-at", "0.2:gain=2.5", "--event-time",
                                "--output", csv_file, "--plot", svg_file});
  model.stop();
  ASSERT_EQ(recorded.exit_code, ExitCode::success) << recorded.err;
  EXPECT_NE(recorded.err.find("wrote gain=2.5 after 0.2"), std::string::npos) << recorded.err;
  EXPECT_EQ(target.parameters[3], 0x40);  // 2.5f is 0x40200000, little-endian

  auto figure = plot::read_csv(read_text_file(csv_file).value(), csv_file);
  ASSERT_TRUE(figure.ok()) << figure.error();
  const plot::Figure& samples = figure.value();
  ASSERT_EQ(samples.series.size(), 2U);
  ASSERT_GT(samples.time.size(), 50U);
  for (std::size_t k = 0; k < samples.time.size(); ++k) {
    EXPECT_DOUBLE_EQ(samples.time[k], static_cast<double>(k) * 0.001);  // the event's period, not the timestamps
  }
  EXPECT_EQ(samples.series[1].values.front(), 0.0);
  EXPECT_EQ(samples.series[1].values.back(), 2.5);
  const std::string svg = read_text_file(svg_file).value();
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find(">gain<"), std::string::npos);
  std::filesystem::remove(csv_file);
  std::filesystem::remove(svg_file);

  EXPECT_EQ(run({"xcp", "record", "--a2l", a2l_file, "--signal", "counter", "--event", "1 ms", "--duration", "0.1",
                 "--write-at", "0.2:gain=1"})
                .err,
            "duet xcp: '0.2:gain=1': after the recording's end (--duration)\n");
  EXPECT_EQ(
      run({"xcp", "record", "--a2l", a2l_file, "--signal", "counter", "--event", "1 ms", "--write-at", "soon:gain=1"})
          .err,
      "duet xcp: 'soon:gain=1': expected SECONDS:NAME=VALUE\n");
  EXPECT_EQ(
      run({"xcp", "record", "--a2l", a2l_file, "--signal", "counter", "--event", "1 ms", "--write-at", "0:gain=1000"})
          .err,
      "duet xcp: gain: 1000 is outside 0 .. 100\n");
}

TEST_F(XcpCommand, ChecksumAndPages) {
  const Outcome checksum = run({"xcp", "checksum", "--connect", endpoint, "0x2000", "8"});
  ASSERT_EQ(checksum.exit_code, ExitCode::success) << checksum.err;
  EXPECT_EQ(checksum.out, "0x0000313E\n");  // CRC16-CCITT of eight zero bytes
  const Outcome switched = run({"xcp", "page", "--connect", endpoint, "--segment", "0", "--page", "1", "--ecu"});
  ASSERT_EQ(switched.exit_code, ExitCode::success) << switched.err;
  EXPECT_EQ(switched.out, "segment 0: ECU page 1, XCP page 0 (0 working, 1 reference)\n");
  EXPECT_EQ(target.ecu_page, target.reference.data());
  const Outcome bad_segment = run({"xcp", "page", "--connect", endpoint, "--segment", "3"});
  EXPECT_EQ(bad_segment.err, "duet xcp: GET_CAL_PAGE: ERR_SEGMENT_NOT_VALID (0x28)\n");
}

// A CSV that cannot be written (here: a full device) ends the recording with an error, not with samples lost quietly.
TEST_F(XcpCommand, RecordFailsWhenItsCsvCannotBeWritten) {
  SteppingModel model{target};
  const Outcome recorded = run({"xcp", "record", "--a2l", a2l_file, "--signal", "counter", "--event", "1 ms",
                                "--duration", "0.2", "--output", "/dev/full"});
  model.stop();
  EXPECT_EQ(recorded.exit_code, ExitCode::failure);
  EXPECT_NE(recorded.err.find("duet xcp: /dev/full: writing the samples failed after "), std::string::npos)
      << recorded.err;
  EXPECT_FALSE(target.slave.connected());  // DAQ stopped and the session ended all the same
}

TEST_F(XcpCommand, RecordFailsWhenNoSampleComes) {
  const Outcome recorded = run({"xcp", "record", "--a2l", a2l_file, "--signal", "counter", "--event", "1 ms",
                                "--duration", "0.1"});  // the model does not step: no event
  EXPECT_EQ(recorded.exit_code, ExitCode::failure);
  EXPECT_NE(recorded.err.find("recorded 0 samples"), std::string::npos) << recorded.err;
  EXPECT_NE(recorded.err.find("duet xcp: no sample came in 0.1 s: is event '1 ms' running?\n"), std::string::npos)
      << recorded.err;
}

// A slave like a widely used slave library on Ethernet, scripted byte for byte: relative ODT numbers with an aligned
// DAQ list word, fixed 4-byte timestamps in 1 us, every packet padded to 4 bytes. The recording's times go on across
// the clock's wrap; a packet of a list not the master's counts as lost, and so the command fails.
TEST_F(XcpCommand, RecordGoesOnAcrossTheClocksWrapAndFailsWhenPacketsAreLost) {
  constexpr const char* ok = "FF 00 00 00";
  ScriptedSlave slave{{
      {"FF 00", {"FF 05 80 FF DC 05 01 01"}},
      {"DA", {"FF 11 00 01 03 00 00 C0"}},
      {"D9", {"FF 01 F8 01 00 3C 01 00"}},
      {"F6 00 00 00 00 40 00 00", {ok}},                               // the EPK's address, from the A2L
      {"F5 0D", {"FF 64 75 65 74 5F 74 61 72 67 65 74 20 31 00 00"}},  // "duet_target 1", padded
      {"D6", {ok}},
      {"D5 00 01 00", {ok}},
      {"D4 00 00 00 01", {ok}},
      {"D3 00 00 00 00 02", {ok}},
      {"E2 00 00 00 00 00", {ok}},
      {"E1 FF 04 00 00 10 00 00", {ok}},
      {"E1 FF 02 00 04 10 00 00", {ok}},
      {"E0 10 00 00 00 00 01 00", {ok}},
      {"DE 02 00 00", {ok}},
      {"DD 01",
       {ok, "00 00 00 00 F0 FF FF FF 01 00 00 00 02 00 00 00", "00 00 00 00 10 00 00 00 02 00 00 00 04 00 00 00",
        "00 00 07 00 20 00 00 00 00 00 00 00 00 00 00 00", "00 00 00 00 30 00 00 00 03 00 00 00 06 00 00 00"}},
      {"DD 00", {ok}},
      {"FE", {ok}},
  }};
  const std::string connect = "tcp://127.0.0.1:" + std::to_string(slave.port());
  const std::string csv_file = a2l_file + ".csv";
  const Outcome recorded = run({"xcp", "record", "--connect", connect, "--a2l", a2l_file, "--signal", "counter",
                                "--signal", "twice", "--event", "1 ms", "--duration", "0.2", "--output", csv_file});
  EXPECT_EQ(slave.differences(), "");
  EXPECT_EQ(recorded.exit_code, ExitCode::failure);
  EXPECT_NE(recorded.err.find("recorded 3 samples of 2 signals on event '1 ms' (0 overloads, 0 lost packets, 1 "
                              "discarded: 1 of unknown ODTs, 0 too short, 0 of incomplete samples, 0 unexpected; 3 "
                              "with fill bytes)\nduet xcp: samples were lost (see the counts above)\n"),
            std::string::npos)
      << recorded.err;
  EXPECT_EQ(read_text_file(csv_file).value(), "time_s,counter,twice\n0,1,2\n3.2e-05,2,4\n6.4e-05,3,6\n");
  std::filesystem::remove(csv_file);
}

// GET_ID with the identification in the response (mode bit 0), and an error answer that fails the command.
TEST_F(XcpCommand, InfoReadsTheIdentificationFromTheResponseAndFailsOnAnErrorAnswer) {
  ScriptedSlave slave{{
      {"FF 00", {"FF 05 81 08 00 20 01 01"}},
      {"DA", {"FF 11 00 01 00 01 00 80"}},
      {"D9", {"FF 01 1D 00 00 32 00 01"}},
      {"FA 01", {"FF 01 00 00 00 00 00 04 70 75 6D 70"}},  // "pump", Motorola length
      {"FE", {"FE 31"}},
  }};
  const Outcome info = run({"xcp", "info", "--connect", "tcp://127.0.0.1:" + std::to_string(slave.port())});
  EXPECT_EQ(slave.differences(), "");
  EXPECT_EQ(info.exit_code, ExitCode::failure);
  EXPECT_EQ(info.out,
            "slave        pump\nMAX_CTO      8\nMAX_DTO      32\nprotocol     1, transport 1\nbyte order   Motorola\n"
            "resources    calibration/paging DAQ\nDAQ packets  relative ODT number, DAQ list word; 2-byte timestamps "
            "of 1e-06 s\n");
  EXPECT_EQ(info.err, "duet xcp: DISCONNECT: ERR_GENERIC (0x31)\n");
}

TEST_F(XcpCommand, UsageAndConnectionErrorsAreClear) {
  EXPECT_EQ(run({"xcp", "info"}).err, "duet xcp: no slave to talk to: give --connect tcp://host:port or --a2l FILE\n");
  EXPECT_EQ(run({"xcp", "info", "--connect", "ftp://x:1"}).err,
            "duet xcp: 'ftp://x:1': unknown scheme (expected tcp://host:port or udp://host:port)\n");
  EXPECT_EQ(run({"xcp", "list", "--a2l", "/nonexistent.a2l"}).err, "duet xcp: /nonexistent.a2l: cannot open\n");
  EXPECT_EQ(run({"xcp"}).exit_code, ExitCode::usage);
  EXPECT_EQ(run({"xcp", "frobnicate"}).exit_code, ExitCode::usage);
}

}  // namespace
}  // namespace duet::cli
