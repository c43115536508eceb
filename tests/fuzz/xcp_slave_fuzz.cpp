// libFuzzer target: arbitrary packets into an XCP slave with real declared memory (so AddressSanitizer sees every
// byte it may touch), calibration pages, DAQ storage and a transmit queue. The input's first byte chooses the packet
// layout (identification field, timestamp size, byte order); the rest is a sequence of packets, each prefixed with
// its length; between packets, events sample DAQ and the transport drains the queue.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/xcp/slave.hpp"

namespace {

using namespace duet::xcp;

std::size_t make_seed(std::uint8_t, std::span<std::uint8_t> seed) {
  for (std::size_t byte = 0; byte < 6; ++byte) seed[byte] = static_cast<std::uint8_t>(0x30 + byte);
  return 6;
}
bool key_is_valid(std::uint8_t, std::span<const std::uint8_t> seed, std::span<const std::uint8_t> key) {
  return key.size() == seed.size() && key[0] == static_cast<std::uint8_t>(seed[0] ^ 0x5A);
}

struct Target {
  std::array<std::uint8_t, 64> measurements{};
  std::array<std::uint8_t, 32> parameters{};
  std::array<std::uint8_t, 16> working{};
  std::array<std::uint8_t, 16> reference{};
  const std::uint8_t* volatile ecu_page = working.data();
  std::array<std::uint8_t, 512> download_buffer{};
  std::array<MemoryRegion, 2> regions{
      MemoryRegion{.name = "measurements", .address = 0x1000, .size = 64, .memory = measurements.data()},
      MemoryRegion{.name = "parameters",
                   .extension = 1,
                   .address = 0xFFFF'FFE0,  // at the very end of the address space
                   .size = 32,
                   .memory = parameters.data(),
                   .access = Access::read_write}};
  std::array<CalibrationSegment, 1> segments{CalibrationSegment{.name = "tuning",
                                                                .address = 0x3000,
                                                                .size = 16,
                                                                .working = working.data(),
                                                                .reference = reference.data(),
                                                                .ecu_page = &ecu_page}};
  std::array<EventChannel, 3> events{EventChannel{.name = "base"}, EventChannel{.name = "slow"},
                                     EventChannel{.name = "uart"}};
  std::array<DaqList, 4> lists{};
  std::array<Odt, 8> odts{};
  std::array<OdtEntry, 24> entries{};
  std::array<std::uint8_t, 512> queue_storage{};
  TransmitQueue queue{queue_storage, {}};
  SlaveConfiguration configuration{.memory = MemoryMap{regions},
                                   .segments = segments,
                                   .max_cto = 64,
                                   .max_dto = 128,
                                   .identification = "fuzz",
                                   .protected_resources = resource::daq,
                                   .seed_and_key = {make_seed, key_is_valid},
                                   .download_buffer = download_buffer,
                                   .events = events,
                                   .daq = {lists, odts, entries},
                                   .queue = &queue};
  Slave slave{configuration};
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  Target target;
  const std::uint8_t layout = data[0];
  constexpr std::array timestamp_sizes{TimestampSize::byte, TimestampSize::word, TimestampSize::dword,
                                       TimestampSize::dword};
  target.configuration.identification_field = static_cast<IdentificationField>(layout & 0x03U);
  target.configuration.timestamp_size = timestamp_sizes[(layout >> 2U) & 0x03U];
  target.configuration.byte_order = (layout & 0x10U) != 0 ? ByteOrder::motorola : ByteOrder::intel;
  target.configuration.identification_in_response = (layout & 0x20U) != 0;
  const std::array<std::uint8_t, 2> connect{0xFF, 0x00};
  (void)target.slave.handle(connect);
  std::array<std::uint8_t, 256> sent{};
  std::size_t at = 1;
  while (at < size) {
    const std::size_t length = data[at++];
    const std::size_t available = size - at < length ? size - at : length;
    const std::span<const std::uint8_t> response = target.slave.handle({data + at, available});
    if (response.size() > target.configuration.max_cto) __builtin_trap();  // never longer than MAX_CTO
    at += available;
    target.slave.on_event(static_cast<std::uint16_t>(length % 4));  // event 3 does not exist
    if (length % 3 == 0) {
      while (target.queue.pop(sent) != 0) {
      }
    }
  }
  return 0;
}
