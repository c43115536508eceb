#pragma once
// What the slave's tests share: hex <-> bytes, sessions of (request, exact expected response), and a slave with
// declared memory, seed & key, a USER_CMD hook and DAQ storage. Test code only.

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "duet/xcp/slave.hpp"

namespace duet::xcp::slave_testing {

inline std::vector<std::uint8_t> from_hex(const std::string& text) {
  std::vector<std::uint8_t> bytes;
  std::istringstream stream{text};
  std::string byte;
  while (stream >> byte) bytes.push_back(static_cast<std::uint8_t>(std::stoul(byte, nullptr, 16)));
  return bytes;
}

inline std::string to_hex(std::span<const std::uint8_t> bytes) {
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
  void (*configure)(SlaveConfiguration&) = nullptr;  // a variant of the fixture's configuration
};

// Seed 01 02 03 04 (for DAQ 01 .. 14, longer than one packet); the key is the seed XOR 0x5A: 5B 58 59 5E.
inline std::size_t make_seed(std::uint8_t resource, std::span<std::uint8_t> seed) {
  const std::size_t length = resource == resource::daq ? 20 : 4;
  for (std::size_t byte = 0; byte < length; ++byte) seed[byte] = static_cast<std::uint8_t>(byte + 1);
  return length;
}
inline bool key_is_valid(std::uint8_t, std::span<const std::uint8_t> seed, std::span<const std::uint8_t> key) {
  if (key.size() != seed.size()) return false;
  for (std::size_t byte = 0; byte < seed.size(); ++byte) {
    if (key[byte] != (seed[byte] ^ 0x5AU)) return false;
  }
  return true;
}
// USER_CMD: subcommand 0x01 answers its parameter plus one; anything else is ERR_SUBCMD_UNKNOWN.
inline bool user_command(PacketReader& request, PacketWriter& response, Error& error) {
  if (request.u8() != 0x01) {
    error = Error::subcmd_unknown;
    return false;
  }
  response.u8(static_cast<std::uint8_t>(request.u8() + 1));
  return true;
}

// A slave with declared memory, seed & key, a USER_CMD hook and DAQ: measurements 00 01 .. 0F at 0x1000 (read-only),
// parameters 32 x 0xAA at 0x2000 (read-write), two event channels, room for 4 DAQ lists, 8 ODTs, 16 entries.
class SlaveFixture : public ::testing::Test {
 protected:
  static std::uint32_t fixed_timestamp() { return 0x1122'3344; }

  SlaveConfiguration make_configuration(std::uint8_t protected_resources = 0, bool with_user_command = true) {
    for (std::size_t byte = 0; byte < measurements.size(); ++byte) measurements[byte] = static_cast<std::uint8_t>(byte);
    parameters.fill(0xAA);
    for (std::size_t byte = 0; byte < working.size(); ++byte) working[byte] = static_cast<std::uint8_t>(byte + 1);
    return {
        .memory = MemoryMap{regions},
        .segments = segments,
        .max_cto = 16,
        .max_dto = 1024,
        .identification = "duet_test",
        .a2l = a2l,
        .protected_resources = protected_resources,
        .seed_and_key = {make_seed, key_is_valid},
        .user_command = with_user_command ? user_command : nullptr,
        .download_buffer = download_buffer,
        .events = events,
        .daq = {daq_lists, odts, entries},
        .queue = &queue,
        .timestamp = fixed_timestamp,
    };
  }

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
  // A calibration segment of 8 bytes at 0x3000: working page 01 .. 08, reference page 10 .. 17.
  std::array<std::uint8_t, 8> working{};
  static constexpr std::array<std::uint8_t, 8> reference{0x10, 0x11, 0x12, 0x13, 0x14, 0x15, 0x16, 0x17};
  const std::uint8_t* volatile ecu_page = working.data();
  std::array<CalibrationSegment, 1> segments{CalibrationSegment{.name = "tuning",
                                                                .address = 0x3000,
                                                                .size = 8,
                                                                .working = working.data(),
                                                                .reference = reference.data(),
                                                                .ecu_page = &ecu_page}};
  static constexpr std::array<EventChannel, 2> events{EventChannel{.name = "1 ms", .time_cycle = 1, .time_unit = 6},
                                                      EventChannel{.name = "uart", .priority = 2}};
  std::array<DaqList, 4> daq_lists{};
  std::array<Odt, 8> odts{};
  std::array<OdtEntry, 16> entries{};
  std::array<std::uint8_t, 4096> queue_storage{};
  TransmitQueue queue{queue_storage, {}};
};

// Runs requests that must all succeed.
inline void run(Slave& slave, const std::vector<std::string>& requests) {
  for (const std::string& request : requests) {
    const std::vector<std::uint8_t> bytes = from_hex(request);
    ASSERT_EQ(to_hex(slave.handle(bytes)).substr(0, 2), "FF") << request;
  }
}

inline std::vector<std::string> drain(TransmitQueue& queue) {
  std::vector<std::string> packets;
  std::array<std::uint8_t, 1024> packet{};
  while (const std::size_t size = queue.pop(packet)) packets.push_back(to_hex(std::span{packet}.first(size)));
  return packets;
}

}  // namespace duet::xcp::slave_testing
