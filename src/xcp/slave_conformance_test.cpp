// The slave's conformance suite: sessions written as tables of (request, exact expected response), byte for byte.
// Requests and responses are hex; "" as a response means the slave must stay silent.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "duet/xcp/slave.hpp"

namespace duet::xcp {
namespace {

std::vector<std::uint8_t> from_hex(const std::string& text) {
  std::vector<std::uint8_t> bytes;
  std::istringstream stream{text};
  std::string byte;
  while (stream >> byte) bytes.push_back(static_cast<std::uint8_t>(std::stoul(byte, nullptr, 16)));
  return bytes;
}

std::string to_hex(std::span<const std::uint8_t> bytes) {
  std::string text;
  static constexpr char digits[] = "0123456789ABCDEF";
  for (std::uint8_t byte : bytes) {
    if (!text.empty()) text += ' ';
    text += digits[byte >> 4U];
    text += digits[byte & 0xFU];
  }
  return text;
}

struct Step {
  std::string request;
  std::string response;
};

struct Session {
  std::string name;
  std::vector<Step> steps;
  std::uint8_t protected_resources = 0;
  bool with_user_command = true;
};

// Seed 01 02 03 04 (for DAQ 01 .. 14, longer than one packet); the key is the seed XOR 0x5A: 5B 58 59 5E.
std::size_t make_seed(std::uint8_t resource, std::span<std::uint8_t> seed) {
  const std::size_t length = resource == resource::daq ? 20 : 4;
  for (std::size_t byte = 0; byte < length; ++byte) seed[byte] = static_cast<std::uint8_t>(byte + 1);
  return length;
}
bool key_is_valid(std::uint8_t, std::span<const std::uint8_t> seed, std::span<const std::uint8_t> key) {
  if (key.size() != seed.size()) return false;
  for (std::size_t byte = 0; byte < seed.size(); ++byte) {
    if (key[byte] != (seed[byte] ^ 0x5AU)) return false;
  }
  return true;
}
// USER_CMD: subcommand 0x01 answers its parameter plus one; anything else is ERR_SUBCMD_UNKNOWN.
bool user_command(PacketReader& request, PacketWriter& response, Error& error) {
  if (request.u8() != 0x01) {
    error = Error::subcmd_unknown;
    return false;
  }
  response.u8(static_cast<std::uint8_t>(request.u8() + 1));
  return true;
}

class SlaveConformance : public ::testing::TestWithParam<Session> {
 protected:
  // Measurements: 00 01 .. 0F at 0x1000, read-only. Parameters: 32 bytes of 0xAA at 0x2000, read-write.
  std::array<std::uint8_t, 16> measurements{};
  std::array<std::uint8_t, 32> parameters{};
  std::array<std::uint8_t, 64> download_buffer{};
  std::array<MemoryRegion, 2> regions{
      MemoryRegion{.name = "measurements", .address = 0x1000, .size = 16, .memory = measurements.data()},
      MemoryRegion{.name = "parameters",
                   .address = 0x2000,
                   .size = 32,
                   .memory = parameters.data(),
                   .access = Access::read_write}};
  static constexpr std::array<std::uint8_t, 4> a2l{'A', '2', 'L', '!'};
};

TEST_P(SlaveConformance, AnswersEveryRequestExactly) {
  const Session& session = GetParam();
  for (std::size_t byte = 0; byte < measurements.size(); ++byte) measurements[byte] = static_cast<std::uint8_t>(byte);
  parameters.fill(0xAA);
  const SlaveConfiguration configuration{
      .memory = MemoryMap{regions},
      .max_cto = 16,
      .max_dto = 1024,
      .identification = "duet_test",
      .a2l = a2l,
      .protected_resources = session.protected_resources,
      .seed_and_key = {make_seed, key_is_valid},
      .user_command = session.with_user_command ? user_command : nullptr,
      .download_buffer = download_buffer,
  };
  Slave slave{configuration};
  for (const Step& step : session.steps) {
    const std::vector<std::uint8_t> request = from_hex(step.request);
    EXPECT_EQ(to_hex(slave.handle(request)), step.response) << "request " << step.request;
  }
}

const std::string connect = "FF 00";
const std::string connected = "FF 01 80 10 00 04 01 01";

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
                 {"F3 00 00 00 00 00 00 00", "FE 22 00 00 10 00"},
                 {"F3 00 00 00 01 00 10 00", "FE 22 00 00 10 00"}}},
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
        Session{"a_wrong_key_ends_the_session",
                {{connect, connected},
                 {"F8 00 01", "FF 04 01 02 03 04"},
                 {"F7 04 00 00 00 00", "FE 25"},
                 {"FD", ""},
                 {connect, connected},
                 {"FD", "FF 00 01 00 00 00"}},  // locked again
                resource::calibration_paging}),
    [](const ::testing::TestParamInfo<Session>& session) { return session.param.name; });

}  // namespace
}  // namespace duet::xcp
