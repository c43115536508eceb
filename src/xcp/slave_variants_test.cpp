// The slave in its other configurations, byte for byte against the standard's layouts: Motorola byte order, GET_ID
// with the identification in the response, checksum alignment, and DAQ packets with each identification field type
// and timestamp size. Requests and responses are hex, as in slave_test.cpp.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "duet/xcp/slave.hpp"
#include "slave_test_fixture.hpp"

namespace duet::xcp {
namespace {

using namespace slave_testing;

class SlaveVariant : public SlaveFixture, public ::testing::WithParamInterface<Session> {};

TEST_P(SlaveVariant, AnswersEveryRequestExactly) {
  const Session& session = GetParam();
  SlaveConfiguration configuration = make_configuration(session.protected_resources, session.with_user_command);
  session.configure(configuration);
  Slave slave{configuration};
  for (const Step& step : session.steps) {
    const std::vector<std::uint8_t> request = from_hex(step.request);
    EXPECT_EQ(to_hex(slave.handle(request)), step.response) << "request " << step.request;
  }
}

void motorola(SlaveConfiguration& configuration) { configuration.byte_order = ByteOrder::motorola; }
void short_identification_in_response(SlaveConfiguration& configuration) {
  configuration.identification = "duet";
  configuration.identification_in_response = true;
}
void long_identification_in_response(SlaveConfiguration& configuration) {
  configuration.identification_in_response = true;  // "duet_test" and the header take 17 bytes: more than MAX_CTO
}
void motorola_identification_in_response(SlaveConfiguration& configuration) {
  motorola(configuration);
  short_identification_in_response(configuration);
}
void word_checksum(SlaveConfiguration& configuration) { configuration.checksum_type = ChecksumType::add_22; }
void aligned_identification_small_dto(SlaveConfiguration& configuration) {
  configuration.identification_field = IdentificationField::relative_word_aligned;
  configuration.max_dto = 64;
}

INSTANTIATE_TEST_SUITE_P(
    Configurations, SlaveVariant,
    ::testing::Values(
        // Every multi-byte field of commands and responses big-endian; memory contents as the firmware keeps them.
        Session{"motorola",
                {{"FF 00", "FF 05 81 10 04 00 01 01"},  // COMM_MODE_BASIC bit 0; MAX_DTO 0x0400
                 {"FD", "FF 00 00 00 00 00"},
                 {"F6 00 00 00 00 00 10 00", "FF"},  // SET_MTA 0x00001000
                 {"F5 04", "FF 00 01 02 03"},
                 {"F4 02 00 00 00 00 10 0E", "FF 0E 0F"},
                 {"F6 00 00 00 00 00 10 00", "FF"},
                 {"F3 00 00 00 00 00 00 10", "FF 08 00 00 00 00 3B 37"},  // CRC16-CCITT 0x3B37
                 {"F3 00 00 00 00 00 00 00", "FE 22 00 01 00 10 00 00"},
                 {"FA 01", "FF 00 00 00 00 00 00 09"},
                 {"F5 09", "FF 64 75 65 74 5F 74 65 73 74"},
                 {"E8 00 00 00 00", "FF 00 00 00 00 00 30 00"},
                 {"E8 00 00 01 00", "FF 00 00 00 00 00 00 08"},
                 {"ED 04 00 00 00 00 20 00 78 56 34 12", "FF"},
                 {"F6 00 00 00 00 00 20 00", "FF"},
                 {"EC 04 FF 0F 00 F0", "FF"},  // AND 0xFF0F, XOR 0x00F0, shifted by 4
                 {"F4 04 00 00 00 00 20 00", "FF 78 5F 34 12"},
                 {"DA", "FF 93 00 04 00 02 00 00"},
                 {"D9", "FF 01 FF 01 00 34 00 01"},
                 {"D7 00 00 01", "FF 84 FF 04 00 00 02"},
                 {"DC", "FF 00 00 00 11 22 33 44"},
                 {"D6", "FF"},
                 {"D5 00 00 01", "FF"},
                 {"D4 00 00 00 01", "FF"},
                 {"D3 00 00 00 00 01", "FF"},
                 {"E2 00 00 00 00 00", "FF"},
                 {"E1 FF 04 00 00 00 10 00", "FF"},
                 {"E2 00 00 00 00 00", "FF"},
                 {"DB", "FF FF 04 00 00 00 10 00"},
                 {"E0 10 00 00 00 01 02 00", "FF"},  // list 0, event 1, prescaler 2
                 {"DF 00 00 00", "FF 10 00 00 00 01 02 00"},
                 {"D8 00 00 00", "FF 04 01 01 00 00"},
                 {"DE 02 00 00", "FF 00"},
                 {"D8 00 00 01", "FE 22"}},
                0,
                true,
                motorola},
        // GET_ID mode bit 0: the identification follows the length in the response.
        Session{"identification_in_the_response",
                {{"FF 00", "FF 05 80 10 00 04 01 01"},
                 {"FA 01", "FF 01 00 00 04 00 00 00 64 75 65 74"},
                 {"FA 00", "FF 01 00 00 04 00 00 00 64 75 65 74"},
                 {"FA 04", "FF 00 00 00 04 00 00 00"},  // the A2L always through the MTA
                 {"F5 04", "FF 41 32 4C 21"},
                 {"FA 02", "FF 00 00 00 00 00 00 00"}},  // no path known: length 0
                0,
                true,
                short_identification_in_response},
        Session{"identification_too_long_for_the_response",
                {{"FF 00", "FF 05 80 10 00 04 01 01"},
                 {"FA 01", "FF 00 00 00 09 00 00 00"},
                 {"F5 09", "FF 64 75 65 74 5F 74 65 73 74"}},
                0,
                true,
                long_identification_in_response},
        Session{"motorola_identification_in_the_response",
                {{"FF 00", "FF 05 81 10 04 00 01 01"}, {"FA 01", "FF 01 00 00 00 00 00 04 64 75 65 74"}},
                0,
                true,
                motorola_identification_in_response},
        // ADD_22 sums words: the MTA and the block size must be multiples of 2 (MTA_BLOCK_SIZE_ALIGN).
        Session{"checksum_alignment",
                {{"FF 00", "FF 05 80 10 00 04 01 01"},
                 {"F6 00 00 00 01 10 00 00", "FF"},
                 {"F3 00 00 00 02 00 00 00", "FE 22 02 00 00 00 10 00"},
                 {"F6 00 00 00 00 10 00 00", "FF"},
                 {"F3 00 00 00 03 00 00 00", "FE 22 02 00 00 00 10 00"},
                 {"F3 00 00 00 04 00 00 00", "FF 04 00 00 02 04 00 00"}},  // 0x0100 + 0x0302
                0,
                true,
                word_checksum},
        // The largest entry leaves room for the identification (4 bytes) and the timestamp (4) in MAX_DTO (64).
        Session{"entries_fit_the_first_packet",
                {{"FF 00", "FF 05 80 10 40 00 01 01"},
                 {"DA", "FF 93 04 00 02 00 00 C0"},
                 {"D9", "FF 01 38 01 00 34 01 00"},
                 {"D6", "FF"},
                 {"D5 00 01 00", "FF"},
                 {"D4 00 00 00 01", "FF"},
                 {"D3 00 00 00 00 02", "FF"},
                 {"E2 00 00 00 00 00", "FF"},
                 {"E1 FF 39 00 00 10 00 00", "FE 22"},
                 {"E1 FF 38 00 00 10 00 00", "FE 24"},  // fits, but the region has 16 bytes
                 {"E1 FF 10 00 00 10 00 00", "FF"}},
                0,
                true,
                aligned_identification_small_dto}),
    [](const ::testing::TestParamInfo<Session>& session) { return session.param.name; });

// One layout of DAQ packets: the configuration, what GET_DAQ_PROCESSOR_INFO, GET_DAQ_RESOLUTION_INFO and
// START_STOP_DAQ_LIST say about it, and the two packets of one sample of list 1, as the standard lays them out.
struct PacketLayout {
  std::string name;
  IdentificationField field = IdentificationField::absolute;
  TimestampSize timestamp = TimestampSize::dword;
  ByteOrder order = ByteOrder::intel;
  std::string processor_info;
  std::string resolution_info;
  std::string first_pid;
  std::vector<std::string> packets;
};

class DaqPacketLayout : public SlaveFixture, public ::testing::WithParamInterface<PacketLayout> {};

// Two lists, so that list 1's number and absolute PIDs are not 0. List 1 on event 0 with timestamps: ODT 0 = 4 bytes
// at 0x1000, ODT 1 = 2 bytes at 0x100E. The clock reads 0x11223344.
std::vector<std::string> list_one(ByteOrder order) {
  if (order == ByteOrder::intel) {
    return {"D6",
            "D5 00 02 00",
            "D4 00 00 00 01",
            "D4 00 01 00 02",
            "D3 00 00 00 00 01",
            "D3 00 01 00 00 01",
            "D3 00 01 00 01 01",
            "E2 00 01 00 00 00",
            "E1 FF 04 00 00 10 00 00",
            "E2 00 01 00 01 00",
            "E1 FF 02 00 0E 10 00 00",
            "E2 00 00 00 00 00",
            "E1 FF 01 00 00 20 00 00",
            "E0 10 01 00 00 00 01 00"};
  }
  return {"D6",
          "D5 00 00 02",
          "D4 00 00 00 01",
          "D4 00 00 01 02",
          "D3 00 00 00 00 01",
          "D3 00 00 01 00 01",
          "D3 00 00 01 01 01",
          "E2 00 00 01 00 00",
          "E1 FF 04 00 00 00 10 00",
          "E2 00 00 01 01 00",
          "E1 FF 02 00 00 00 10 0E",
          "E2 00 00 00 00 00",
          "E1 FF 01 00 00 00 20 00",
          "E0 10 00 01 00 00 01 00"};
}

TEST_P(DaqPacketLayout, SamplesAsTheStandardLaysThemOut) {
  const PacketLayout& layout = GetParam();
  SlaveConfiguration configuration = make_configuration();
  configuration.identification_field = layout.field;
  configuration.timestamp_size = layout.timestamp;
  configuration.byte_order = layout.order;
  configuration.max_dto = 64;
  Slave slave{configuration};
  run(slave, {"FF 00"});
  EXPECT_EQ(to_hex(slave.handle(from_hex("DA"))), layout.processor_info);
  EXPECT_EQ(to_hex(slave.handle(from_hex("D9"))), layout.resolution_info);
  run(slave, list_one(layout.order));
  const std::string start = layout.order == ByteOrder::intel ? "DE 01 01 00" : "DE 01 00 01";
  EXPECT_EQ(to_hex(slave.handle(from_hex(start))), layout.first_pid);
  slave.on_event(0);
  EXPECT_EQ(drain(queue), layout.packets);
  slave.on_event(1);  // no list on event 1
  EXPECT_TRUE(queue.empty());
}

using enum IdentificationField;
using enum TimestampSize;
constexpr ByteOrder intel = ByteOrder::intel;
constexpr ByteOrder motorola_order = ByteOrder::motorola;

INSTANTIATE_TEST_SUITE_P(Layouts, DaqPacketLayout,
                         ::testing::Values(PacketLayout{"absolute_dword",
                                                        absolute,
                                                        dword,
                                                        intel,
                                                        "FF 93 04 00 02 00 00 00",
                                                        "FF 01 3B 01 00 34 01 00",
                                                        "FF 01",
                                                        {"01 44 33 22 11 00 01 02 03", "02 0E 0F"}},
                                           PacketLayout{"absolute_word",
                                                        absolute,
                                                        word,
                                                        intel,
                                                        "FF 93 04 00 02 00 00 00",
                                                        "FF 01 3D 01 00 32 01 00",
                                                        "FF 01",
                                                        {"01 44 33 00 01 02 03", "02 0E 0F"}},
                                           PacketLayout{"absolute_byte",
                                                        absolute,
                                                        byte,
                                                        intel,
                                                        "FF 93 04 00 02 00 00 00",
                                                        "FF 01 3E 01 00 31 01 00",
                                                        "FF 01",
                                                        {"01 44 00 01 02 03", "02 0E 0F"}},
                                           PacketLayout{"absolute_dword_motorola",
                                                        absolute,
                                                        dword,
                                                        motorola_order,
                                                        "FF 93 00 04 00 02 00 00",
                                                        "FF 01 3B 01 00 34 00 01",
                                                        "FF 01",
                                                        {"01 11 22 33 44 00 01 02 03", "02 0E 0F"}},
                                           PacketLayout{"absolute_word_motorola",
                                                        absolute,
                                                        word,
                                                        motorola_order,
                                                        "FF 93 00 04 00 02 00 00",
                                                        "FF 01 3D 01 00 32 00 01",
                                                        "FF 01",
                                                        {"01 33 44 00 01 02 03", "02 0E 0F"}},
                                           PacketLayout{"relative_byte_dword",
                                                        relative_byte,
                                                        dword,
                                                        intel,
                                                        "FF 93 04 00 02 00 00 40",
                                                        "FF 01 3A 01 00 34 01 00",
                                                        "FF 00",
                                                        {"00 01 44 33 22 11 00 01 02 03", "01 01 0E 0F"}},
                                           PacketLayout{"relative_byte_byte_motorola",
                                                        relative_byte,
                                                        byte,
                                                        motorola_order,
                                                        "FF 93 00 04 00 02 00 40",
                                                        "FF 01 3D 01 00 31 00 01",
                                                        "FF 00",
                                                        {"00 01 44 00 01 02 03", "01 01 0E 0F"}},
                                           PacketLayout{"relative_word_word",
                                                        relative_word,
                                                        word,
                                                        intel,
                                                        "FF 93 04 00 02 00 00 80",
                                                        "FF 01 3B 01 00 32 01 00",
                                                        "FF 00",
                                                        {"00 01 00 44 33 00 01 02 03", "01 01 00 0E 0F"}},
                                           PacketLayout{"relative_word_dword_motorola",
                                                        relative_word,
                                                        dword,
                                                        motorola_order,
                                                        "FF 93 00 04 00 02 00 80",
                                                        "FF 01 39 01 00 34 00 01",
                                                        "FF 00",
                                                        {"00 00 01 11 22 33 44 00 01 02 03", "01 00 01 0E 0F"}},
                                           PacketLayout{"relative_word_aligned_dword",
                                                        relative_word_aligned,
                                                        dword,
                                                        intel,
                                                        "FF 93 04 00 02 00 00 C0",
                                                        "FF 01 38 01 00 34 01 00",
                                                        "FF 00",
                                                        {"00 00 01 00 44 33 22 11 00 01 02 03", "01 00 01 00 0E 0F"}},
                                           PacketLayout{"relative_word_aligned_word_motorola",
                                                        relative_word_aligned,
                                                        word,
                                                        motorola_order,
                                                        "FF 93 00 04 00 02 00 C0",
                                                        "FF 01 3A 01 00 32 00 01",
                                                        "FF 00",
                                                        {"00 00 00 01 33 44 00 01 02 03", "01 00 00 01 0E 0F"}},
                                           PacketLayout{"relative_word_aligned_byte",
                                                        relative_word_aligned,
                                                        byte,
                                                        intel,
                                                        "FF 93 04 00 02 00 00 C0",
                                                        "FF 01 3B 01 00 31 01 00",
                                                        "FF 00",
                                                        {"00 00 01 00 44 00 01 02 03", "01 00 01 00 0E 0F"}}),
                         [](const ::testing::TestParamInfo<PacketLayout>& layout) { return layout.param.name; });

}  // namespace
}  // namespace duet::xcp
