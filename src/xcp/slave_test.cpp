// The slave's conformance suite: sessions written as tables of (request, exact expected response), byte for byte.
// Requests and responses are hex; "" as a response means the slave must stay silent.

#include "duet/xcp/slave.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "slave_test_fixture.hpp"

namespace duet::xcp {
namespace {

using namespace slave_testing;

class SlaveConformance : public SlaveFixture, public ::testing::WithParamInterface<Session> {};

TEST_P(SlaveConformance, AnswersEveryRequestExactly) {
  const Session& session = GetParam();
  SlaveConfiguration configuration = make_configuration(session.protected_resources, session.with_user_command);
  if (session.configure != nullptr) session.configure(configuration);
  Slave slave{configuration};
  for (const Step& step : session.steps) {
    const std::vector<std::uint8_t> request = from_hex(step.request);
    EXPECT_EQ(to_hex(slave.handle(request)), step.response) << "request " << step.request;
  }
}

constexpr const char* connect = "FF 00";
constexpr const char* connected = "FF 05 80 10 00 04 01 01";  // CAL/PAG and DAQ

INSTANTIATE_TEST_SUITE_P(
    Sessions, SlaveConformance,
    ::testing::Values(
        Session{"connect_and_disconnect",
                {{"FD", ""},  // not connected: silence, except for CONNECT
                 {connect, connected},
                 {"FF 01", connected},  // user-defined mode, and connecting again
                 {"FF 02", "FE 22"},
                 {"FF", "FE 21"},
                 {"FD", "FF 00 00 00 00 00"},
                 {"FE", "FF"},
                 {"FD", ""}}},
        Session{"synch_unknown_and_comm_mode",
                {{connect, connected},
                 {"FC", "FE 00"},
                 {"FB", "FF 00 01 00 FF 00 00 10"},
                 {"C5", "FE 20"},
                 {"10 00", "FE 20"},  // a STIM packet: no STIM here
                 {"C0 00", "FE 20"},
                 {"F2 00", "FE 20"}}},
        Session{"identification_through_the_mta",
                {{connect, connected},
                 {"FA 01", "FF 00 00 00 09 00 00 00"},
                 {"F5 09", "FF 64 75 65 74 5F 74 65 73 74"},  // "duet_test"
                 {"F5 01", "FE 24"},                          // nothing left
                 {"FA 04", "FF 00 00 00 04 00 00 00"},
                 {"F5 04", "FF 41 32 4C 21"},  // the A2L
                 {"FA 02", "FF 00 00 00 00 00 00 00"},
                 {"FA", "FE 21"}}},
        Session{"upload_and_short_upload",
                {{connect, connected},
                 {"F6 00 00 00 00 10 00 00", "FF"},
                 {"F5 04", "FF 00 01 02 03"},
                 {"F5 04", "FF 04 05 06 07"},  // the MTA moved on
                 {"F5 00", "FE 22"},
                 {"F5 10", "FE 22"},  // more than MAX_CTO - 1
                 {"F5 0F", "FE 24"},  // past the region's end
                 {"F4 02 00 00 0E 10 00 00", "FF 0E 0F"},
                 {"F4 02 00 00 0F 10 00 00", "FE 24"},
                 {"F4 02 00 01 00 10 00 00", "FE 24"},  // another address extension
                 {"F4 02 00 00 00 00 00 00", "FE 24"},  // undeclared memory
                 {"F4 02 00 00 00 10 00", "FE 21"},
                 {"F6 00 00 00 00 10", "FE 21"}}},
        Session{"build_checksum",
                {{connect, connected},
                 {"F6 00 00 00 00 10 00 00", "FF"},
                 // CRC16-CCITT of 00 01 .. 0F is 0x3B37.
                 {"F3 00 00 00 10 00 00 00", "FF 08 00 00 37 3B 00 00"},
                 {"F3 00 00 00 01 00 00 00", "FE 24"},  // the MTA is past the region now
                 // ERR_OUT_OF_RANGE: MTA_BLOCK_SIZE_ALIGN (word) at byte 2, the largest block (dword) at byte 4.
                 {"F3 00 00 00 00 00 00 00", "FE 22 01 00 00 00 10 00"},
                 {"F3 00 00 00 01 00 10 00", "FE 22 01 00 00 00 10 00"}}},
        Session{"user_command", {{connect, connected}, {"F1 01 41", "FF 42"}, {"F1 02", "FE 34"}, {"F1", "FE 21"}}},
        Session{"user_command_absent", {{connect, connected}, {"F1 01 41", "FE 20"}}, 0, false},
        Session{"download_short_download_download_max",
                {{connect, connected},
                 {"F6 00 00 00 00 20 00 00", "FF"},
                 {"F0 02 11 22", "FF"},
                 {"F0 02 33 44", "FF"},
                 {"F4 05 00 00 00 20 00 00", "FF 11 22 33 44 AA"},
                 {"F0 00", "FE 22"},
                 {"F0 03 11 22", "FE 21"},
                 {"F6 00 00 00 00 10 00 00", "FF"},
                 {"F0 01 55", "FE 24"},  // measurements are read-only
                 {"ED 02 00 00 1E 20 00 00 66 77", "FF"},
                 {"ED 02 00 00 1F 20 00 00 66 77", "FE 24"},
                 {"ED 09 00 00 00 20 00 00 01 02 03 04 05 06 07 08", "FE 22"},  // more than MAX_CTO - 8
                 {"F4 02 00 00 1E 20 00 00", "FF 66 77"},
                 {"F6 00 00 00 08 20 00 00", "FF"},
                 {"EE 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E 0F", "FF"},
                 {"EE 01 02", "FE 21"},
                 {"F4 0F 00 00 08 20 00 00", "FF 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E 0F"}}},
        Session{"download_sequence",
                {{connect, connected},
                 {"F6 00 00 00 00 20 00 00", "FF"},
                 // 20 bytes: 14 in DOWNLOAD, 6 in DOWNLOAD_NEXT; nothing is written before the last one.
                 {"F0 14 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E", ""},
                 {"EF 05 0F 10 11 12 13", "FE 29 06"},  // the wrong count ends the sequence
                 {"F4 02 00 00 00 20 00 00", "FF AA AA"},
                 {"F6 00 00 00 00 20 00 00", "FF"},
                 {"F0 14 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E", ""},
                 {"EF 06 0F 10 11 12 13 14", "FF"},
                 {"F4 0F 00 00 00 20 00 00", "FF 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E 0F"},
                 {"EF 06 0F 10 11 12 13 14", "FE 29 00"},  // no sequence open
                 {"F6 00 00 00 10 20 00 00", "FF"},
                 {"F0 14 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E", "FE 24"},  // 20 bytes do not fit there
                 {"F6 00 00 00 00 20 00 00", "FF"},
                 {"F0 41", "FE 22"}}},  // longer than the download buffer
        Session{"modify_bits",
                {{connect, connected},
                 {"ED 04 00 00 00 20 00 00 78 56 34 12", "FF"},
                 {"F6 00 00 00 00 20 00 00", "FF"},  // SHORT_DOWNLOAD left the MTA behind the value
                 // Shift 4, AND 0xFF0F, XOR 0x00F0: bits 8-11 are cleared, then all four set: 0x12345F78.
                 {"EC 04 0F FF F0 00", "FF"},
                 {"EC 04 FF FF 00 00", "FF"},  // the MTA stays: AND all ones, XOR none leaves the value
                 {"F4 04 00 00 00 20 00 00", "FF 78 5F 34 12"},
                 {"EC 11 FF FF 00 00", "FE 22"},
                 {"F6 00 00 00 00 10 00 00", "FF"},
                 {"EC 00 FF FF 01 00", "FE 24"},
                 {"EC 00 FF", "FE 21"}}},
        Session{"seed_and_key",
                {{connect, connected},
                 {"FD", "FF 00 01 00 00 00"},
                 {"F6 00 00 00 00 20 00 00", "FF"},
                 {"F0 01 01", "FE 25"},
                 {"EC 00 FF FF 01 00", "FE 25"},
                 {"F7 04 5B 58 59 5E", "FE 29"},  // no seed asked for
                 {"F8 00 03", "FE 22"},           // two resources at once
                 {"F8 02 01", "FE 22"},
                 {"F8 01 01", "FE 29"},
                 {"F8 00 04", "FF 00"},  // DAQ is not protected
                 {"F8 00 01", "FF 04 01 02 03 04"},
                 {"F7 05 5B 58 59 5E", "FE 21"},  // announces five key bytes, brings four
                 {"F8 00 01", "FF 04 01 02 03 04"},
                 {"F7 04 5B 58 59 5E", "FF 00"},
                 {"F0 01 01", "FF"}},
                resource::calibration_paging},
        Session{"seed_and_key_in_several_packets",
                {{connect, connected},
                 {"F8 00 04", "FF 14 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E"},
                 {"F7 14 5B 58 59 5E 5F 5C 5D 52 53 50 51 56 57 54", "FE 29"},  // the seed is not all sent yet
                 {"F8 01 04", "FF 06 0F 10 11 12 13 14"},
                 {"F8 01 04", "FE 29"},
                 {"F7 14 5B 58 59 5E 5F 5C 5D 52 53 50 51 56 57 54", "FF 04"},  // 14 of 20 key bytes: still locked
                 {"F7 06 55 4A 4B 48 49 4E", "FF 00"}},
                resource::daq},
        Session{"paging",
                {{connect, connected},
                 {"E9", "FF 01 00"},
                 {"E8 00 00 00 00", "FF 00 00 00 00 30 00 00"},
                 {"E8 00 00 01 00", "FF 00 00 00 08 00 00 00"},
                 {"E8 01 00 00 00", "FF 02 00 00 00 00"},
                 {"E8 02 00 00 00", "FE 22"},
                 {"E8 00 01 00 00", "FE 28"},
                 {"E7 00 00 00", "FF 3F 00"},
                 {"E7 00 00 01", "FF 0F 00"},
                 {"E7 00 00 02", "FE 26"},
                 {"EA 01 00", "FF 00 00 00"},
                 {"EA 03 00", "FE 27"},
                 {"F4 02 00 00 00 30 00 00", "FF 01 02"},
                 {"EB 02 00 01", "FF"},  // XCP sees the reference page
                 {"F4 02 00 00 00 30 00 00", "FF 10 11"},
                 {"ED 01 00 00 00 30 00 00 55", "FE 24"},  // which is read-only
                 {"EA 02 00", "FF 00 00 01"},
                 {"EA 01 00", "FF 00 00 00"},  // the model still reads the working page
                 {"EB 01 00 01", "FF"},
                 {"EA 01 00", "FF 00 00 01"},
                 {"EB 83 00 00", "FF"},  // all segments, ECU and XCP, back to the working page
                 {"F4 02 00 00 00 30 00 00", "FF 01 02"},
                 {"ED 02 00 00 00 30 00 00 55 66", "FF"},
                 {"F4 02 00 00 00 30 00 00", "FF 55 66"},
                 {"E4 00 01 00 00", "FF"},  // reset the working page to the reference
                 {"F4 02 00 00 00 30 00 00", "FF 10 11"},
                 {"E4 00 00 00 01", "FE 23"},
                 {"E4 00 02 00 00", "FE 26"},
                 {"E4 01 01 01 00", "FE 28"},
                 {"EB 04 00 00", "FE 27"},
                 {"EB 01 01 00", "FE 28"},
                 {"EB 01 00 02", "FE 26"},
                 {"E6 01 00", "FE 27"},
                 {"E6 00 00", "FF"},
                 {"E5 00 00", "FF 00 00"},
                 {"E5 00 05", "FE 28"}}},
        Session{"daq_information",
                {{connect, connected},
                 {"DA", "FF 93 04 00 02 00 00 00"},
                 {"D9", "FF 01 FF 01 00 34 01 00"},
                 {"D7 00 00 00", "FF 84 FF 04 01 06 00"},
                 {"F5 04", "FF 31 20 6D 73"},  // "1 ms"
                 {"D7 00 01 00", "FF 84 FF 04 00 00 02"},
                 {"D7 00 02 00", "FE 22"},
                 {"DC", "FF 00 00 00 44 33 22 11"}}},
        Session{"daq_configuration",
                {{connect, connected},
                 {"D4 00 00 00 01", "FE 29"},  // ALLOC_ODT before ALLOC_DAQ
                 {"D6", "FF"},
                 {"D5 00 05 00", "FE 30"},
                 {"D5 00 02 00", "FF"},
                 {"D5 00 01 00", "FE 29"},
                 {"D3 00 00 00 00 01", "FE 29"},  // ALLOC_ODT_ENTRY before ALLOC_ODT
                 {"D4 00 02 00 01", "FE 22"},
                 {"D4 00 00 00 02", "FF"},
                 {"D4 00 01 00 01", "FF"},
                 {"D4 00 01 00 01", "FE 29"},  // list 1 has its ODTs already
                 {"D3 00 00 00 00 02", "FF"},
                 {"D3 00 00 00 01 01", "FF"},
                 {"D3 00 01 00 00 01", "FF"},
                 {"D3 00 01 00 01 01", "FE 22"},
                 {"D3 00 00 00 02 10", "FE 22"},
                 {"D4 00 01 00 01", "FE 29"},           // no more ODTs once entries are allocated
                 {"E1 FF 04 00 00 10 00 00", "FE 29"},  // no DAQ pointer yet
                 {"E2 00 00 00 00 00", "FF"},
                 {"E1 FF 04 00 00 10 00 00", "FF"},
                 {"E1 FF 02 00 04 10 00 00", "FF"},
                 {"E1 FF 02 00 06 10 00 00", "FE 29"},  // past the ODT's entries
                 {"E2 00 00 00 01 00", "FF"},
                 {"E1 FF 04 00 00 00 00 00", "FE 24"},  // undeclared memory
                 {"E1 00 04 00 00 10 00 00", "FE 22"},  // bit offsets are not offered
                 {"E1 FF 00 00 00 10 00 00", "FE 22"},
                 {"C7 01 FF 02 0E 10 00 00 00 00", "FF"},
                 {"C7 02 FF 02 0E 10 00 00 00 00", "FE 21"},
                 {"E2 00 00 00 00 00", "FF"},
                 {"DB", "FF FF 04 00 00 10 00 00"},
                 {"DB", "FF FF 02 00 04 10 00 00"},
                 {"DB", "FE 29"},
                 {"E2 00 03 00 00 00", "FE 22"},
                 {"E2 00 01 00 00 00", "FF"},
                 {"E1 FF 01 00 00 20 00 00", "FF"},  // parameters can be measured too
                 {"DE 01 00 00", "FE 2A"},           // no event yet
                 {"E0 10 00 00 00 00 01 00", "FF"},
                 {"E0 02 01 00 01 00 01 00", "FE 27"},  // STIM
                 {"E0 00 01 00 02 00 01 00", "FE 22"},  // no event 2
                 {"E0 00 01 00 01 00 00 00", "FE 22"},  // prescaler 0
                 {"E0 00 01 00 01 00 02 00", "FF"},
                 {"DF 00 00 00", "FF 10 00 00 00 00 01 00"},
                 {"DE 02 00 00", "FF 00"},
                 {"DE 02 01 00", "FF 02"},
                 {"DF 00 01 00", "FF 01 00 00 01 00 02 00"},
                 {"DD 01", "FF"},
                 {"FD", "FF 40 00 00 00 00"},
                 {"DF 00 00 00", "FF 50 00 00 00 00 01 00"},
                 {"E2 00 00 00 00 00", "FE 11"},
                 {"E0 10 00 00 00 00 01 00", "FE 11"},
                 {"D8 00 00 00", "FF 04 02 02 00 00"},
                 {"D8 00 04 00", "FE 22"},
                 {"DD 03", "FE 22"},
                 {"DD 00", "FF"},
                 {"FD", "FF 00 00 00 00 00"},
                 {"E3 00 00 00", "FF"},
                 {"DE 01 00 00", "FE 2A"}}},  // cleared entries make the list incomplete
        Session{
            "daq_locked", {{connect, connected}, {"D6", "FE 25"}, {"DA", "FF 93 04 00 02 00 00 00"}}, resource::daq},
        Session{"a_wrong_key_ends_the_session",
                {{connect, connected},
                 {"F8 00 01", "FF 04 01 02 03 04"},
                 {"F7 04 00 00 00 00", "FE 25"},
                 {"FD", ""},
                 {connect, connected},
                 {"FD", "FF 00 01 00 00 00"}},  // locked again
                resource::calibration_paging}),
    [](const ::testing::TestParamInfo<Session>& session) { return session.param.name; });

// List 0 on event 0 with timestamps: ODT 0 = 4 bytes at 0x1000 and 2 at 0x1004, ODT 1 = 2 bytes at 0x100E.
// List 1 on event 1 every second time: 1 byte at 0x2000.
std::vector<std::string> two_lists() {
  return {"FF 00",
          "D6",
          "D5 00 02 00",
          "D4 00 00 00 02",
          "D4 00 01 00 01",
          "D3 00 00 00 00 02",
          "D3 00 00 00 01 01",
          "D3 00 01 00 00 01",
          "E2 00 00 00 00 00",
          "E1 FF 04 00 00 10 00 00",
          "E1 FF 02 00 04 10 00 00",
          "E2 00 00 00 01 00",
          "E1 FF 02 00 0E 10 00 00",
          "E2 00 01 00 00 00",
          "E1 FF 01 00 00 20 00 00",
          "E0 10 00 00 00 00 01 00",
          "E0 00 01 00 01 00 02 00",
          "DE 02 00 00",
          "DE 02 01 00",
          "DD 01"};
}

TEST_F(SlaveFixture, EventsSampleTheirListsIntoWholePackets) {
  const SlaveConfiguration configuration = make_configuration();
  Slave slave{configuration};
  run(slave, two_lists());
  slave.on_event(0);
  slave.on_event(1);  // prescaler 2: not yet
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"00 44 33 22 11 00 01 02 03 04 05", "01 0E 0F"}));
  measurements[0] = 0x77;
  slave.on_event(1);
  slave.on_event(0);
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"02 AA", "00 44 33 22 11 77 01 02 03 04 05", "01 0E 0F"}));
  run(slave, {"DD 00"});
  slave.on_event(0);
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(slave.overloads(), 0U);
}

TEST_F(SlaveFixture, ASampleThatDoesNotFitIsDroppedWholeCountedAndAnnounced) {
  std::array<std::uint8_t, 40> small{};  // one sample of list 0 (18 bytes of records) plus the headroom of 18
  TransmitQueue small_queue{small, {}};
  SlaveConfiguration configuration = make_configuration();
  configuration.queue = &small_queue;
  Slave slave{configuration};
  run(slave, two_lists());
  slave.on_event(0);
  slave.on_event(0);  // no room: dropped whole
  EXPECT_EQ(slave.overloads(), 1U);
  EXPECT_EQ(drain(small_queue), (std::vector<std::string>{"00 44 33 22 11 00 01 02 03 04 05", "01 0E 0F"}));
  slave.on_event(1);
  slave.on_event(1);  // the next sample that fits comes after EV_DAQ_OVERLOAD
  EXPECT_EQ(drain(small_queue), (std::vector<std::string>{"FD 06", "02 AA"}));
}

// List 0 on event 0 without timestamps: one ODT of two four-byte entries, at 0x1000 and 0x1008.
std::vector<std::string> one_list_of_words() {
  return {"FF 00",
          "D6",
          "D5 00 01 00",
          "D4 00 00 00 01",
          "D3 00 00 00 00 02",
          "E2 00 00 00 00 00",
          "E1 FF 04 00 00 10 00 00",
          "E1 FF 04 00 08 10 00 00",
          "E0 00 00 00 00 00 01 00",
          "DE 01 00 00"};
}

// An ODT whose entries are all four bytes long is copied without reading each entry's size: the sizes are taken
// again when the list starts again after the master rewrote an entry.
TEST_F(SlaveFixture, EntrySizesAreTakenAgainWhenAListStarts) {
  const SlaveConfiguration configuration = make_configuration();
  Slave slave{configuration};
  run(slave, one_list_of_words());
  slave.on_event(0);
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"00 00 01 02 03 08 09 0A 0B"}));
  run(slave, {"DE 00 00 00", "E2 00 00 00 00 01", "E1 FF 02 00 0C 10 00 00", "DE 01 00 00"});
  slave.on_event(0);
  EXPECT_EQ(drain(queue), (std::vector<std::string>{"00 00 01 02 03 0C 0D"}));
}

TEST_F(SlaveFixture, FourByteEntriesWrapRoundTheRing) {
  std::array<std::uint8_t, 40> small{};  // samples of 11 bytes of records: the fourth wraps round
  TransmitQueue small_queue{small, {}};
  SlaveConfiguration configuration = make_configuration();
  configuration.queue = &small_queue;
  Slave slave{configuration};
  run(slave, one_list_of_words());
  for (int sample = 0; sample < 5; ++sample) {
    measurements[8] = static_cast<std::uint8_t>(sample);
    slave.on_event(0);
    EXPECT_EQ(drain(small_queue), (std::vector<std::string>{"00 00 01 02 03 0" + std::to_string(sample) + " 09 0A 0B"}))
        << sample;
  }
  EXPECT_EQ(slave.overloads(), 0U);
}

TEST_F(SlaveFixture, TheEcuPageIsThePointerTheModelReadsThrough) {
  const SlaveConfiguration configuration = make_configuration();
  Slave slave{configuration};
  run(slave, {"FF 00", "EB 01 00 01"});
  EXPECT_EQ(ecu_page, reference.data());
  run(slave, {"EB 81 00 00"});
  EXPECT_EQ(ecu_page, working.data());
}

TEST_F(SlaveFixture, DisconnectStopsDaq) {
  const SlaveConfiguration configuration = make_configuration();
  Slave slave{configuration};
  run(slave, two_lists());
  run(slave, {"FE"});
  slave.on_event(0);
  EXPECT_TRUE(queue.empty());
}

}  // namespace
}  // namespace duet::xcp
