// The master's commands: session, memory, checksum, identification, seed & key, pages. Multi-byte fields go both
// ways in the slave's byte order; responses may be longer than their layout (fill bytes), never shorter.

#include "duet/xcp/host/master.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "command_packet.hpp"
#include "duet/xcp/protocol.hpp"

namespace duet::xcp::host {
namespace {

// COMM_MODE_BASIC bits 1-2: the size of an address's element.
constexpr std::uint8_t address_granularity_bits = 0x06;
constexpr std::uint8_t motorola_bit = 0x01;
constexpr std::uint8_t smallest_max_cto = 8;
// GET_ID's mode byte.
constexpr std::uint8_t id_in_response = 0x01;
constexpr std::uint8_t id_compressed_or_encrypted = 0x02;
constexpr std::size_t id_response_header = 8;
constexpr std::uint32_t largest_identification = 64U << 20U;  // an A2L of 64 MB is no identification

std::string error_message(std::string_view name, std::span<const std::uint8_t> packet) {
  const std::uint8_t code = packet.size() > 1 ? packet[1] : 0;
  char hex[8];
  std::snprintf(hex, sizeof(hex), "0x%02X", code);
  return std::string{name} + ": " + xcp::name(static_cast<Error>(code)) + " (" + hex + ")";
}

Failure too_short(std::string_view name) { return Failure{std::string{name} + ": the response is too short"}; }

}  // namespace

Master::Master(std::unique_ptr<MasterChannel> channel, std::chrono::milliseconds timeout)
    : channel_(std::move(channel)), timeout_(timeout) {}

PacketCounters Master::counters() const {
  PacketCounters counters = counters_;
  counters.counter_gaps = channel_->counter_gaps();
  return counters;
}

Result<std::vector<std::uint8_t>> Master::exchange(std::span<const std::uint8_t> request, std::string_view name) {
  if (Status sent = channel_->send(request); !sent) return Failure{std::string{name} + ": " + sent.error()};
  const auto deadline = std::chrono::steady_clock::now() + timeout_;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0)
      return Failure{std::string{name} + ": no response within " + std::to_string(timeout_.count()) + " ms"};
    auto received = channel_->receive(left);
    if (!received) return Failure{std::string{name} + ": " + received.error()};
    if (!received.value()) continue;
    std::vector<std::uint8_t> packet = std::move(*received.value());
    if (packet[0] == pid::response || packet[0] == pid::error) return packet;
    take_asynchronous(std::move(packet));
  }
}

// ERR_CMD_BUSY asks for the command again: the standard's answer is to wait and repeat it. A slave still busy with
// something, or a bridge whose line to the slave is not open yet, says it; the master repeats until its timeout has
// passed since the first try.
Result<std::vector<std::uint8_t>> Master::command(std::span<const std::uint8_t> request, std::string_view name) {
  const auto give_up = std::chrono::steady_clock::now() + timeout_;
  for (;;) {
    auto answer = exchange(request, name);
    if (!answer) return answer;
    const std::vector<std::uint8_t>& packet = answer.value();
    if (packet[0] != pid::error) return answer;
    const bool busy = packet.size() > 1 && packet[1] == static_cast<std::uint8_t>(Error::cmd_busy);
    if (!busy || std::chrono::steady_clock::now() >= give_up) return Failure{error_message(name, packet)};
    channel_->restart_counter();
    std::this_thread::sleep_for(std::chrono::milliseconds{10});
  }
}

Result<SlaveProperties> Master::connect() {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::connect), 0};
  auto response = command(request, "CONNECT");
  if (!response) return Failure{response.error()};
  const std::vector<std::uint8_t>& bytes = response.value();
  if (bytes.size() < 8) return too_short("CONNECT");
  const std::uint8_t comm_mode_basic = bytes[2];
  if ((comm_mode_basic & address_granularity_bits) != 0) {
    return Failure{"CONNECT: the slave addresses memory in elements of " +
                   std::to_string(1U << ((comm_mode_basic & address_granularity_bits) >> 1U)) +
                   " bytes; this master handles byte addresses only"};
  }
  if (bytes[3] < smallest_max_cto) {
    return Failure{"CONNECT: MAX_CTO " + std::to_string(bytes[3]) + " is below the standard's least, 8"};
  }
  const ByteOrder order = (comm_mode_basic & motorola_bit) != 0 ? ByteOrder::motorola : ByteOrder::intel;
  PacketReader fields{bytes, order};
  fields.skip(4);
  const std::uint16_t max_dto = fields.u16();
  properties_ = {bytes[1], comm_mode_basic, bytes[3], max_dto, bytes[6], bytes[7], order};
  daq_processor_.reset();
  layouts_.clear();
  by_pid_.clear();
  if ((properties_.resources & resource::daq) != 0) {
    // A slave may answer these only after UNLOCK; start_daq() asks again.
    (void)read_daq_processor();
  }
  return properties_;
}

Status Master::disconnect() {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::disconnect)};
  auto response = command(request, "DISCONNECT");
  return response ? done() : Status{Failure{response.error()}};
}

Status Master::set_mta(std::uint8_t extension, std::uint32_t address) {
  const CommandPacket request =
      CommandPacket{Command::set_mta, properties_.byte_order}.u8(0).u8(0).u8(extension).u32(address);
  auto response = command(request.packet(), "SET_MTA");
  return response ? done() : Status{Failure{response.error()}};
}

Result<std::vector<std::uint8_t>> Master::upload_at_mta(std::uint32_t size) {
  std::vector<std::uint8_t> bytes;
  const std::uint32_t chunk_limit = properties_.max_cto - 1U;
  while (bytes.size() < size) {
    const auto chunk = static_cast<std::uint8_t>(
        std::min<std::uint32_t>(chunk_limit, size - static_cast<std::uint32_t>(bytes.size())));
    const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::upload), chunk};
    auto response = command(request, "UPLOAD");
    if (!response) return Failure{response.error()};
    if (response.value().size() < 1U + chunk) {
      return Failure{"UPLOAD: " + std::to_string(response.value().size() - 1) + " of " + std::to_string(chunk) +
                     " bytes came"};
    }
    bytes.insert(bytes.end(), response.value().begin() + 1, response.value().begin() + 1 + chunk);
  }
  return bytes;
}

Result<std::vector<std::uint8_t>> Master::upload(std::uint8_t extension, std::uint32_t address, std::uint32_t size) {
  if (Status mta = set_mta(extension, address); !mta) return Failure{mta.error()};
  return upload_at_mta(size);
}

Status Master::download(std::uint8_t extension, std::uint32_t address, std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return done();
  if (bytes.size() > 255) return Failure{"DOWNLOAD: at most 255 bytes at once"};
  if (Status mta = set_mta(extension, address); !mta) return Failure{mta.error()};
  const std::size_t room = properties_.max_cto - 2U;
  std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::download),
                                    static_cast<std::uint8_t>(bytes.size())};
  const std::size_t first = std::min(room, bytes.size());
  request.insert(request.end(), bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(first));
  if (first == bytes.size()) {
    auto response = command(request, "DOWNLOAD");
    return response ? done() : Status{Failure{response.error()}};
  }
  // Master block mode: the slave answers only the last DOWNLOAD_NEXT (or an error at any point).
  if (Status sent = channel_->send(request); !sent) return Failure{"DOWNLOAD: " + sent.error()};
  std::size_t at = first;
  while (at < bytes.size()) {
    const std::size_t part = std::min(room, bytes.size() - at);
    std::vector<std::uint8_t> next{static_cast<std::uint8_t>(Command::download_next),
                                   static_cast<std::uint8_t>(bytes.size() - at)};
    next.insert(next.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at),
                bytes.begin() + static_cast<std::ptrdiff_t>(at + part));
    at += part;
    if (at < bytes.size()) {
      if (Status sent = channel_->send(next); !sent) return Failure{"DOWNLOAD_NEXT: " + sent.error()};
    } else {
      auto response = command(next, "DOWNLOAD_NEXT");
      return response ? done() : Status{Failure{response.error()}};
    }
  }
  return done();
}

Result<std::uint32_t> Master::checksum(std::uint8_t extension, std::uint32_t address, std::uint32_t size) {
  if (Status mta = set_mta(extension, address); !mta) return Failure{mta.error()};
  const CommandPacket request =
      CommandPacket{Command::build_checksum, properties_.byte_order}.u8(0).u8(0).u8(0).u32(size);
  auto answer = exchange(request.packet(), "BUILD_CHECKSUM");
  if (!answer) return Failure{answer.error()};
  const std::vector<std::uint8_t>& bytes = answer.value();
  PacketReader fields{bytes, properties_.byte_order};
  if (bytes[0] == pid::error) {
    // ERR_OUT_OF_RANGE says why: MTA_BLOCK_SIZE_ALIGN at byte 2, the largest block at byte 4.
    if (bytes.size() >= 8 && bytes[1] == static_cast<std::uint8_t>(Error::out_of_range)) {
      fields.skip(2);
      const std::uint16_t alignment = fields.u16();
      const std::uint32_t largest = fields.u32();
      return Failure{error_message("BUILD_CHECKSUM", bytes) + ": the slave sums at most " + std::to_string(largest) +
                     " bytes at once, from an address and of a size that are multiples of " +
                     std::to_string(alignment)};
    }
    return Failure{error_message("BUILD_CHECKSUM", bytes)};
  }
  if (bytes.size() < 8) return too_short("BUILD_CHECKSUM");
  fields.skip(4);
  return fields.u32();
}

Result<std::vector<std::uint8_t>> Master::identification(std::uint8_t type) {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::get_id), type};
  auto response = command(request, "GET_ID");
  if (!response) return Failure{response.error()};
  const std::vector<std::uint8_t>& bytes = response.value();
  if (bytes.size() < id_response_header) return too_short("GET_ID");
  PacketReader fields{bytes, properties_.byte_order};
  fields.skip(1);
  const std::uint8_t mode = fields.u8();
  fields.skip(2);
  const std::uint32_t length = fields.u32();
  if ((mode & id_compressed_or_encrypted) != 0) {
    return Failure{"GET_ID: the identification is compressed or encrypted, which this master cannot read"};
  }
  if ((mode & id_in_response) != 0) {
    if (bytes.size() - id_response_header < length) {
      return Failure{"GET_ID: the response holds " + std::to_string(bytes.size() - id_response_header) + " of the " +
                     std::to_string(length) + " bytes it announces"};
    }
    const auto begin = bytes.begin() + static_cast<std::ptrdiff_t>(id_response_header);
    return std::vector<std::uint8_t>(begin, begin + static_cast<std::ptrdiff_t>(length));
  }
  if (length > largest_identification) {
    return Failure{"GET_ID: an identification of " + std::to_string(length) + " bytes is not believable"};
  }
  return upload_at_mta(length);
}

Status Master::unlock(std::uint8_t resource, const KeyFunction& key) {
  std::vector<std::uint8_t> seed;
  std::uint8_t mode = 0;
  for (;;) {
    const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::get_seed), mode, resource};
    auto response = command(request, "GET_SEED");
    if (!response) return Failure{response.error()};
    const std::vector<std::uint8_t>& bytes = response.value();
    if (bytes.size() < 2) return too_short("GET_SEED");
    const std::size_t remaining = bytes[1];
    if (remaining == 0 && seed.empty()) return done();  // not protected
    const std::size_t part = std::min<std::size_t>(remaining, properties_.max_cto - 2U);
    if (bytes.size() < 2 + part) return too_short("GET_SEED");
    seed.insert(seed.end(), bytes.begin() + 2, bytes.begin() + 2 + static_cast<std::ptrdiff_t>(part));
    if (part >= remaining) break;
    mode = 1;
  }
  const std::vector<std::uint8_t> computed = key(resource, seed);
  std::size_t at = 0;
  while (at < computed.size()) {
    const std::size_t part = std::min<std::size_t>(properties_.max_cto - 2U, computed.size() - at);
    std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::unlock),
                                      static_cast<std::uint8_t>(computed.size() - at)};
    request.insert(request.end(), computed.begin() + static_cast<std::ptrdiff_t>(at),
                   computed.begin() + static_cast<std::ptrdiff_t>(at + part));
    at += part;
    auto response = command(request, "UNLOCK");
    if (!response) return Failure{response.error()};
    if (response.value().size() < 2) return too_short("UNLOCK");
    if (at == computed.size() && (response.value()[1] & resource) != 0) {
      return Failure{"UNLOCK: the resource is still locked"};
    }
  }
  return done();
}

Status Master::set_calibration_page(std::uint8_t mode, std::uint8_t segment, std::uint8_t page) {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::set_cal_page), mode, segment, page};
  auto response = command(request, "SET_CAL_PAGE");
  return response ? done() : Status{Failure{response.error()}};
}

Result<std::uint8_t> Master::calibration_page(std::uint8_t mode, std::uint8_t segment) {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::get_cal_page), mode, segment};
  auto response = command(request, "GET_CAL_PAGE");
  if (!response) return Failure{response.error()};
  if (response.value().size() < 4) return too_short("GET_CAL_PAGE");
  return response.value()[3];
}

}  // namespace duet::xcp::host
