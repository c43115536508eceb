// The master against scripted slaves, whose every byte is written here from the standard's layouts rather than
// produced by duet's slave: the requests the master must send (the master's conformance table) and the answers of
// two slaves unlike duet's. One identifies DAQ packets by relative ODT number, fill byte and DAQ list word
// (DAQ_KEY_BYTE 0xC0), always sends 4-byte timestamps, pads every packet to 4 bytes and answers GET_ID in the
// response, as a widely used slave library on Ethernet does. The other is Motorola, numbers ODTs absolutely, flags
// overloads in the PID's MSB, stamps 2 bytes in 10 us, has a predefined DAQ list (MIN_DAQ 1), samples entries of at
// most 4 bytes in steps of 2, and has MAX_CTO 8.

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "duet/xcp/host/master.hpp"
#include "duet/xcp/protocol.hpp"
#include "scripted_slave.hpp"

namespace duet::xcp::host {
namespace {

Master connected_master(const ScriptedSlave& slave) {
  auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", slave.port()}, std::chrono::seconds{1});
  EXPECT_TRUE(channel.ok()) << (channel.ok() ? "" : channel.error());
  return Master{std::move(channel).value(), std::chrono::milliseconds{1000}};
}

std::vector<DaqSample> samples_of(Master& master, std::size_t count) {
  std::vector<DaqSample> samples;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds{5};
  while (samples.size() < count && std::chrono::steady_clock::now() < deadline) {
    auto received = master.receive_samples(std::chrono::milliseconds{50});
    EXPECT_TRUE(received.ok()) << (received.ok() ? "" : received.error());
    if (!received.ok()) break;
    for (DaqSample& sample : received.value()) samples.push_back(std::move(sample));
  }
  return samples;
}

constexpr const char* ok4 = "FF 00 00 00";  // a positive response padded to 4 bytes

// ERR_CMD_BUSY is the standard's "wait and repeat": the master repeats the command (here CONNECT twice, as a bridge
// whose line to the slave is not open yet answers) and goes on; any other error ends the command.
TEST(MasterAgainstScriptedSlave, RepeatsACommandTheSlaveIsTooBusyFor) {
  ScriptedSlave slave{{
      {"FF 00", {"FE 10"}},
      {"FF 00", {"FE 10"}},
      {"FF 00", {"FF 01 00 08 08 00 01 01"}},  // CAL/PAG only: no DAQ questions follow
      {"F6 00 00 00 00 10 00 00", {"FE 24"}},  // ERR_ACCESS_DENIED is not repeated
  }};
  Master master = connected_master(slave);
  ASSERT_TRUE(master.connect().ok());
  const auto uploaded = master.upload(0, 0x1000, 4);
  ASSERT_FALSE(uploaded.ok());
  EXPECT_EQ(uploaded.error(), "SET_MTA: ERR_ACCESS_DENIED (0x24)");
  EXPECT_EQ(slave.differences(), "");
}

TEST(MasterAgainstScriptedSlave, RelativeOdtAndAlignedDaqWordWithPaddingAndIdentificationInTheResponse) {
  ScriptedSlave slave{{
      {"FF 00", {"FF 05 80 FF DC 05 01 01"}},  // CAL/PAG and DAQ, Intel, MAX_CTO 255, MAX_DTO 1500
      // Dynamic DAQ with timestamps, MAX_DAQ 256, 3 events, MIN_DAQ 0, DAQ_KEY_BYTE 0xC0.
      {"DA", {"FF 11 00 01 03 00 00 C0"}},
      // Granularity 1, entries of up to 248 bytes, a fixed 4-byte timestamp in 1 us, 1 unit a tick.
      {"D9", {"FF 01 F8 01 00 3C 01 00"}},
      {"FA 01", {"FF 01 00 00 06 00 00 00 65 6E 67 69 6E 65 00 00"}},  // "engine" in the response, 2 fill bytes
      {"F6 00 00 00 00 10 00 00", {ok4}},                              // SET_MTA 0x1000
      {"F5 05", {"FF 01 02 03 04 05 00 00"}},
      {"F6 00 00 00 00 20 00 00", {ok4}},
      {"F0 03 01 02 03", {ok4}},
      {"F6 00 00 00 00 10 00 00", {ok4}},
      {"F3 00 00 00 04 00 00 00", {"FF 09 00 00 78 56 34 12"}},  // CRC32 0x12345678
      {"F6 00 00 00 00 10 00 00", {ok4}},
      {"F3 00 00 00 00 00 10 00", {"FE 22 01 00 00 00 01 00"}},  // alignment 1, at most 0x10000 bytes
      {"F6 00 00 00 00 90 00 00", {ok4}},
      {"F5 01", {"FE 24 00 00"}},
      {"EB 83 00 01", {ok4}},
      {"EA 02 00", {"FF 00 00 01"}},
      {"D6", {ok4}},
      {"D5 00 01 00", {ok4}},
      {"D4 00 00 00 01", {ok4}},
      {"D3 00 00 00 00 02", {ok4}},
      {"E2 00 00 00 00 00", {ok4}},
      {"E1 FF 04 00 00 10 00 00", {ok4}},
      {"E1 FF 02 00 04 10 00 00", {ok4}},
      {"E0 10 00 00 01 00 01 00", {ok4}},  // timestamps, list 0, event 1, prescaler 1, priority 0
      {"DE 02 00 00", {ok4}},              // FIRST_PID means nothing with relative ODT numbers
      {"DD 01",
       {ok4,
        // ODT 0, fill, DAQ list 0, the timestamp, 4 + 2 bytes of entries, 2 fill bytes.
        "00 00 00 00 F0 FF FF FF 01 00 00 00 02 00 00 00", "00 00 00 00 10 00 00 00 02 00 00 00 04 00 00 00",
        "00 00 05 00 20 00 00 00 09 00 00 00 09 00 00 00",  // DAQ list 5: not the master's
        "00 00 00 00 30 00 00 00 03 00 00 00 06 00 00 00"}},
      {"DD 00", {ok4}},
      {"FE", {ok4}},
  }};
  {
    Master master = connected_master(slave);
    const auto properties = master.connect();
    ASSERT_TRUE(properties.ok()) << properties.error();
    EXPECT_EQ(properties.value().max_dto, 1500);
    ASSERT_TRUE(master.daq_processor());
    EXPECT_EQ(master.daq_processor()->identification, IdentificationField::relative_word_aligned);
    EXPECT_TRUE(master.daq_processor()->timestamp_fixed);
    EXPECT_DOUBLE_EQ(master.seconds_per_tick(), 1e-6);

    const auto name = master.identification(1);
    ASSERT_TRUE(name.ok()) << name.error();
    EXPECT_EQ(std::string(name.value().begin(), name.value().end()), "engine");
    const auto bytes = master.upload(0, 0x1000, 5);
    ASSERT_TRUE(bytes.ok()) << bytes.error();
    EXPECT_EQ(bytes.value(), (std::vector<std::uint8_t>{1, 2, 3, 4, 5}));
    const std::array<std::uint8_t, 3> values{1, 2, 3};
    EXPECT_TRUE(master.download(0, 0x2000, values).ok());
    EXPECT_EQ(master.checksum(0, 0x1000, 4).value(), 0x12345678U);
    const auto too_big = master.checksum(0, 0x1000, 0x0010'0000);
    EXPECT_EQ(too_big.ok() ? std::string{} : too_big.error(),
              "BUILD_CHECKSUM: ERR_OUT_OF_RANGE (0x22): the slave sums at most 65536 bytes at once, from an address "
              "and of a size that are multiples of 1");
    const auto denied = master.upload(0, 0x9000, 1);
    EXPECT_EQ(denied.ok() ? std::string{} : denied.error(), "UPLOAD: ERR_ACCESS_DENIED (0x24)");
    EXPECT_TRUE(master.set_calibration_page(0x83, 0, 1).ok());
    EXPECT_EQ(master.calibration_page(0x02, 0).value(), 1);

    const Status started =
        master.start_daq({{.event = 1, .prescaler = 1, .entries = {{0, 0x1000, 4}, {0, 0x1004, 2}}}});
    ASSERT_TRUE(started.ok()) << started.error();
    const std::vector<DaqSample> samples = samples_of(master, 3);
    ASSERT_EQ(samples.size(), 3U);
    for (std::size_t index = 0; index < samples.size(); ++index) {
      const auto number = static_cast<std::uint8_t>(index + 1);
      EXPECT_EQ(samples[index].bytes,
                (std::vector<std::uint8_t>{number, 0, 0, 0, static_cast<std::uint8_t>(2 * number), 0}));
    }
    // 0xFFFFFFF0, then across the wrap 0x10, 0x30: 32 ticks apart.
    EXPECT_EQ(samples[0].ticks, 0xFFFF'FFF0);
    EXPECT_EQ(samples[1].ticks, 0x1'0000'0010);
    EXPECT_EQ(samples[2].ticks, 0x1'0000'0030);
    const PacketCounters counters = master.counters();
    EXPECT_EQ(counters.unknown_identification, 1U);
    EXPECT_EQ(counters.padded, 3U);  // the unknown list's packet is counted as unknown only
    EXPECT_EQ(counters.lost(), 1U);
    EXPECT_TRUE(master.stop_daq().ok());
    EXPECT_TRUE(master.disconnect().ok());
  }
  EXPECT_EQ(slave.differences(), "");
}

// A sample in two ODTs whose second never comes is given, when asked for, as incomplete with its time, in its place;
// an ODT whose sample's first is missing has no time and is only counted.
TEST(MasterAgainstScriptedSlave, DeliversIncompleteSamplesWithTheirTimeWhenAskedTo) {
  ScriptedSlave slave{{
      {"FF 00", {"FF 05 80 FF 0C 00 01 01"}},  // MAX_DTO 12: a 4-byte and a 2-byte entry take two ODTs
      {"DA", {"FF 11 00 01 03 00 00 C0"}},
      {"D9", {"FF 01 F8 01 00 3C 01 00"}},
      {"D6", {ok4}},
      {"D5 00 01 00", {ok4}},
      {"D4 00 00 00 02", {ok4}},
      {"D3 00 00 00 00 01", {ok4}},
      {"D3 00 00 00 01 01", {ok4}},
      {"E2 00 00 00 00 00", {ok4}},
      {"E1 FF 04 00 00 10 00 00", {ok4}},
      {"E2 00 00 00 01 00", {ok4}},
      {"E1 FF 02 00 04 10 00 00", {ok4}},
      {"E0 10 00 00 01 00 01 00", {ok4}},
      {"DE 02 00 00", {ok4}},
      {"DD 01",
       {ok4, "00 00 00 00 10 00 00 00 01 00 00 00", "01 00 00 00 02 00",  // complete
        "00 00 00 00 20 00 00 00 03 00 00 00",                            // its second ODT never comes
        "00 00 00 00 30 00 00 00 05 00 00 00", "01 00 00 00 06 00",       // complete
        "01 00 00 00 07 00"}},                                            // the second ODT alone
      {"DD 00", {ok4}},
      {"FE", {ok4}},
  }};
  {
    Master master = connected_master(slave);
    ASSERT_TRUE(master.connect().ok());
    master.deliver_incomplete_samples(true);
    const Status started =
        master.start_daq({{.event = 1, .prescaler = 1, .entries = {{0, 0x1000, 4}, {0, 0x1004, 2}}}});
    ASSERT_TRUE(started.ok()) << started.error();
    const std::vector<DaqSample> samples = samples_of(master, 3);
    ASSERT_EQ(samples.size(), 3U);
    EXPECT_TRUE(samples[0].complete);
    EXPECT_EQ(samples[0].bytes, (std::vector<std::uint8_t>{1, 0, 0, 0, 2, 0}));
    EXPECT_FALSE(samples[1].complete);
    EXPECT_EQ(samples[1].ticks, 0x20);
    EXPECT_TRUE(samples[1].bytes.empty());
    EXPECT_TRUE(samples[2].complete);
    EXPECT_EQ(samples[2].ticks, 0x30);
    EXPECT_TRUE(master.stop_daq().ok());
    EXPECT_EQ(master.counters().incomplete, 2U);
    EXPECT_TRUE(master.disconnect().ok());
  }
  EXPECT_EQ(slave.differences(), "");
}

TEST(MasterAgainstScriptedSlave, MotorolaAbsoluteWithOverloadInThePidAndSplitEntries) {
  ScriptedSlave slave{{
      {"FF 00", {"FF 05 81 08 00 20 01 01"}},  // Motorola, MAX_CTO 8, MAX_DTO 32
      // Dynamic, prescaler, timestamps, overload in the PID's MSB; MAX_DAQ 4, 2 events, MIN_DAQ 1; absolute.
      {"DA", {"FF 53 00 04 00 02 01 00"}},
      // Entries in steps of 2 bytes up to 4; a 2-byte timestamp in 10 us, 1 unit a tick.
      {"D9", {"FF 02 04 00 00 42 00 01"}},
      {"FA 01", {"FF 00 00 00 00 00 00 0A"}},  // 10 bytes, to upload
      {"F5 07", {"FF 73 65 72 76 6F 5F 61"}},
      {"F5 03", {"FF 78 69 73"}},
      {"F6 00 00 00 00 01 23 40", {"FF"}},
      {"F5 04", {"FF DE AD BE EF"}},
      {"F6 00 00 00 00 01 23 40", {"FF"}},
      {"F3 00 00 00 00 00 00 10", {"FF 05 00 00 00 00 12 34"}},
      {"F6 00 00 00 00 01 23 50", {"FF"}},
      {"F0 0A 01 02 03 04 05 06", {}},  // master block mode: only the last DOWNLOAD_NEXT is answered
      {"EF 04 07 08 09 0A", {"FF"}},
      {"F8 00 04", {"FF 08 A1 A2 A3 A4 A5 A6"}},  // 8 seed bytes, 6 in this packet
      {"F8 01 04", {"FF 02 A7 A8"}},
      {"F7 08 5E 5D 5C 5B 5A 59", {"FF 04"}},
      {"F7 02 58 57", {"FF 00"}},
      {"D6", {"FF"}},
      {"D5 00 00 01", {"FF"}},
      {"D4 00 00 01 01", {"FF"}},  // the first dynamic list is number 1
      {"D3 00 00 01 00 03", {"FF"}},
      {"E2 00 00 01 00 00", {"FF"}},
      {"E1 FF 04 00 00 01 23 40", {"FF"}},  // the 8-byte entry in two pieces of 4
      {"E1 FF 04 00 00 01 23 44", {"FF"}},
      {"E1 FF 02 00 00 01 23 48", {"FF"}},
      {"E0 10 00 01 00 01 02 00", {"FF"}},
      {"DE 02 00 01", {"FF 05"}},  // FIRST_PID 5
      {"DD 01",
       {"FF", "05 FF F0 01 02 03 04 05 06 07 08 09 0A",
        "85 00 10 11 12 13 14 15 16 17 18 19 1A",  // samples were lost before this one
        "06 00 20 00 00 00 00 00 00 00 00 00 00",  // PID 6: no ODT of ours
        "05 00",                                   // too short
        "05 00 30 21 22 23 24 25 26 27 28 29 2A"}},
      {"DD 00", {"FF"}},
      {"FE", {"FF"}},
  }};
  {
    Master master = connected_master(slave);
    const auto properties = master.connect();
    ASSERT_TRUE(properties.ok()) << properties.error();
    EXPECT_EQ(properties.value().byte_order, ByteOrder::motorola);
    EXPECT_EQ(properties.value().max_dto, 32);
    EXPECT_DOUBLE_EQ(master.seconds_per_tick(), 10e-6);
    const auto name = master.identification(1);
    ASSERT_TRUE(name.ok()) << name.error();
    EXPECT_EQ(std::string(name.value().begin(), name.value().end()), "servo_axis");
    EXPECT_EQ(master.upload(0, 0x12340, 4).value(), (std::vector<std::uint8_t>{0xDE, 0xAD, 0xBE, 0xEF}));
    EXPECT_EQ(master.checksum(0, 0x12340, 16).value(), 0x1234U);
    const std::array<std::uint8_t, 10> values{1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    EXPECT_TRUE(master.download(0, 0x12350, values).ok());
    const Status unlocked = master.unlock(resource::daq, [](std::uint8_t, std::span<const std::uint8_t> seed) {
      std::vector<std::uint8_t> key;
      for (std::uint8_t byte : seed) key.push_back(static_cast<std::uint8_t>(~byte));
      return key;
    });
    EXPECT_TRUE(unlocked.ok()) << unlocked.error();

    const Status started =
        master.start_daq({{.event = 1, .prescaler = 2, .entries = {{0, 0x12340, 8}, {0, 0x12348, 2}}}});
    ASSERT_TRUE(started.ok()) << started.error();
    const std::vector<DaqSample> samples = samples_of(master, 3);
    ASSERT_EQ(samples.size(), 3U);
    EXPECT_EQ(samples[1].bytes,
              (std::vector<std::uint8_t>{0x11, 0x12, 0x13, 0x14, 0x15, 0x16, 0x17, 0x18, 0x19, 0x1A}));
    EXPECT_EQ(samples[0].ticks, 0xFFF0);
    EXPECT_EQ(samples[1].ticks, 0x1'0010);
    EXPECT_EQ(samples[2].ticks, 0x1'0030);
    const PacketCounters counters = master.counters();
    EXPECT_EQ(counters.overload_events, 1U);
    EXPECT_EQ(counters.unknown_identification, 1U);
    EXPECT_EQ(counters.too_short, 1U);
    EXPECT_EQ(counters.padded, 0U);
    EXPECT_EQ(counters.lost(), 3U);
    EXPECT_TRUE(master.stop_daq().ok());
    EXPECT_TRUE(master.disconnect().ok());
  }
  EXPECT_EQ(slave.differences(), "");
}

}  // namespace
}  // namespace duet::xcp::host
