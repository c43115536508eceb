#include "duet/xcp/host/master.hpp"

#include <cstdio>

#include "duet/xcp/protocol.hpp"

namespace duet::xcp::host {
namespace {

constexpr std::size_t timestamp_size = 4;

void put_u16(std::vector<std::uint8_t>& bytes, std::uint16_t value) {
  bytes.push_back(static_cast<std::uint8_t>(value));
  bytes.push_back(static_cast<std::uint8_t>(value >> 8U));
}
void put_u32(std::vector<std::uint8_t>& bytes, std::uint32_t value) {
  put_u16(bytes, static_cast<std::uint16_t>(value));
  put_u16(bytes, static_cast<std::uint16_t>(value >> 16U));
}
std::uint32_t get_u32(std::span<const std::uint8_t> bytes, std::size_t at) {
  return static_cast<std::uint32_t>(bytes[at]) | (static_cast<std::uint32_t>(bytes[at + 1]) << 8U) |
         (static_cast<std::uint32_t>(bytes[at + 2]) << 16U) | (static_cast<std::uint32_t>(bytes[at + 3]) << 24U);
}

std::string error_message(std::string_view name, std::uint8_t code) {
  char hex[8];
  std::snprintf(hex, sizeof(hex), "0x%02X", code);
  return std::string{name} + ": " + xcp::name(static_cast<Error>(code)) + " (" + hex + ")";
}

}  // namespace

Master::Master(std::unique_ptr<MasterChannel> channel, std::chrono::milliseconds timeout)
    : channel_(std::move(channel)), timeout_(timeout) {}

void Master::take_asynchronous(std::vector<std::uint8_t> packet) {
  const std::uint8_t pid = packet[0];
  if (pid == pid::event) {
    if (packet.size() > 1 && packet[1] == static_cast<std::uint8_t>(EventCode::daq_overload)) ++overload_events_;
    return;
  }
  if (pid >= pid::service || pid >= odts_by_pid_.size() || odts_by_pid_[pid].payload == 0) return;  // not ours
  const OdtLayout& odt = odts_by_pid_[pid];
  Assembly& assembly = assemblies_[odt.list];
  std::size_t at = 1;
  if (odt.first) {
    if (packet.size() < 1 + timestamp_size) return;
    assembly = {get_u32(packet, 1), {}, true};
    at += timestamp_size;
  }
  if (!assembly.started || packet.size() != at + odt.payload) {  // an incomplete sample: wait for the next one
    assembly.started = false;
    return;
  }
  assembly.bytes.insert(assembly.bytes.end(), packet.begin() + static_cast<std::ptrdiff_t>(at), packet.end());
  if (odt.last) {
    samples_.push_back({odt.list, assembly.timestamp, std::move(assembly.bytes)});
    assembly = {};
  }
}

Result<std::vector<std::uint8_t>> Master::command(std::span<const std::uint8_t> request, std::string_view name) {
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
    if (packet[0] == pid::response) return packet;
    if (packet[0] == pid::error) return Failure{error_message(name, packet.size() > 1 ? packet[1] : 0)};
    take_asynchronous(std::move(packet));
  }
}

Result<SlaveProperties> Master::connect() {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::connect), 0};
  auto response = command(request, "CONNECT");
  if (!response) return Failure{response.error()};
  const std::vector<std::uint8_t>& bytes = response.value();
  if (bytes.size() < 8) return Failure{"CONNECT: the response is too short"};
  if ((bytes[2] & 0x01) != 0) return Failure{"CONNECT: the slave uses Motorola byte order, which this master does not"};
  properties_ = {bytes[1], bytes[2], bytes[3], static_cast<std::uint16_t>(bytes[4] | (bytes[5] << 8U)),
                 bytes[6], bytes[7]};
  return properties_;
}

Status Master::disconnect() {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::disconnect)};
  auto response = command(request, "DISCONNECT");
  return response ? done() : Status{Failure{response.error()}};
}

Status Master::set_mta(std::uint8_t extension, std::uint32_t address) {
  std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::set_mta), 0, 0, extension};
  put_u32(request, address);
  auto response = command(request, "SET_MTA");
  return response ? done() : Status{Failure{response.error()}};
}

Result<std::vector<std::uint8_t>> Master::upload(std::uint8_t extension, std::uint32_t address, std::uint32_t size) {
  if (Status mta = set_mta(extension, address); !mta) return Failure{mta.error()};
  std::vector<std::uint8_t> bytes;
  const std::uint32_t chunk_limit = properties_.max_cto - 1U;
  while (bytes.size() < size) {
    const auto chunk = static_cast<std::uint8_t>(
        std::min<std::uint32_t>(chunk_limit, size - static_cast<std::uint32_t>(bytes.size())));
    const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::upload), chunk};
    auto response = command(request, "UPLOAD");
    if (!response) return Failure{response.error()};
    if (response.value().size() != 1U + chunk) return Failure{"UPLOAD: the response has the wrong length"};
    bytes.insert(bytes.end(), response.value().begin() + 1, response.value().end());
  }
  return bytes;
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
  std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::build_checksum), 0, 0, 0};
  put_u32(request, size);
  auto response = command(request, "BUILD_CHECKSUM");
  if (!response) return Failure{response.error()};
  if (response.value().size() < 8) return Failure{"BUILD_CHECKSUM: the response is too short"};
  return get_u32(response.value(), 4);
}

Result<std::vector<std::uint8_t>> Master::identification(std::uint8_t type) {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::get_id), type};
  auto response = command(request, "GET_ID");
  if (!response) return Failure{response.error()};
  if (response.value().size() < 8) return Failure{"GET_ID: the response is too short"};
  const std::uint32_t length = get_u32(response.value(), 4);
  std::vector<std::uint8_t> identification;
  while (identification.size() < length) {
    const auto chunk =
        static_cast<std::uint8_t>(std::min<std::size_t>(properties_.max_cto - 1U, length - identification.size()));
    const std::vector<std::uint8_t> upload{static_cast<std::uint8_t>(Command::upload), chunk};
    auto part = command(upload, "UPLOAD");
    if (!part) return Failure{part.error()};
    identification.insert(identification.end(), part.value().begin() + 1, part.value().end());
  }
  return identification;
}

Status Master::unlock(std::uint8_t resource, const KeyFunction& key) {
  std::vector<std::uint8_t> seed;
  std::uint8_t mode = 0;
  for (;;) {
    const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::get_seed), mode, resource};
    auto response = command(request, "GET_SEED");
    if (!response) return Failure{response.error()};
    const std::size_t remaining = response.value().size() > 1 ? response.value()[1] : 0;
    if (remaining == 0 && seed.empty()) return done();  // not protected
    seed.insert(seed.end(), response.value().begin() + 2, response.value().end());
    if (response.value().size() - 2 >= remaining) break;
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
    if (at == computed.size() && response.value().size() > 1 && (response.value()[1] & resource) != 0) {
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
  if (response.value().size() < 4) return Failure{"GET_CAL_PAGE: the response is too short"};
  return response.value()[3];
}

Status Master::start_daq(const std::vector<DaqListSetup>& lists) {
  auto run = [this](std::vector<std::uint8_t> request, std::string_view name) -> Status {
    auto response = command(request, name);
    return response ? done() : Status{Failure{response.error()}};
  };
  if (Status freed = run({static_cast<std::uint8_t>(Command::free_daq)}, "FREE_DAQ"); !freed) return freed;
  std::vector<std::uint8_t> alloc{static_cast<std::uint8_t>(Command::alloc_daq), 0};
  put_u16(alloc, static_cast<std::uint16_t>(lists.size()));
  if (Status allocated = run(alloc, "ALLOC_DAQ"); !allocated) return allocated;

  // Split each list's entries into ODTs that fit MAX_DTO (the first carries the timestamp too).
  std::vector<std::vector<std::vector<DaqEntry>>> odts(lists.size());
  for (std::size_t list = 0; list < lists.size(); ++list) {
    std::size_t used = 1 + timestamp_size;
    odts[list].emplace_back();
    for (const DaqEntry& entry : lists[list].entries) {
      if (used + entry.size > properties_.max_dto) {
        odts[list].emplace_back();
        used = 1;
      }
      odts[list].back().push_back(entry);
      used += entry.size;
    }
    std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::alloc_odt), 0};
    put_u16(request, static_cast<std::uint16_t>(list));
    request.push_back(static_cast<std::uint8_t>(odts[list].size()));
    if (Status allocated = run(request, "ALLOC_ODT"); !allocated) return allocated;
  }
  for (std::size_t list = 0; list < lists.size(); ++list) {
    for (std::size_t odt = 0; odt < odts[list].size(); ++odt) {
      std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::alloc_odt_entry), 0};
      put_u16(request, static_cast<std::uint16_t>(list));
      request.push_back(static_cast<std::uint8_t>(odt));
      request.push_back(static_cast<std::uint8_t>(odts[list][odt].size()));
      if (Status allocated = run(request, "ALLOC_ODT_ENTRY"); !allocated) return allocated;
    }
  }
  odts_by_pid_.clear();
  assemblies_.assign(lists.size(), {});
  for (std::size_t list = 0; list < lists.size(); ++list) {
    for (std::size_t odt = 0; odt < odts[list].size(); ++odt) {
      std::vector<std::uint8_t> pointer{static_cast<std::uint8_t>(Command::set_daq_ptr), 0};
      put_u16(pointer, static_cast<std::uint16_t>(list));
      pointer.push_back(static_cast<std::uint8_t>(odt));
      pointer.push_back(0);
      if (Status set = run(pointer, "SET_DAQ_PTR"); !set) return set;
      for (const DaqEntry& entry : odts[list][odt]) {
        std::vector<std::uint8_t> write{static_cast<std::uint8_t>(Command::write_daq), 0xFF, entry.size,
                                        entry.extension};
        put_u32(write, entry.address);
        if (Status written = run(write, "WRITE_DAQ"); !written) return written;
      }
    }
    std::vector<std::uint8_t> mode{static_cast<std::uint8_t>(Command::set_daq_list_mode), 0x10};  // timestamps
    put_u16(mode, static_cast<std::uint16_t>(list));
    put_u16(mode, lists[list].event);
    mode.push_back(lists[list].prescaler);
    mode.push_back(0);
    if (Status set = run(mode, "SET_DAQ_LIST_MODE"); !set) return set;
    std::vector<std::uint8_t> select{static_cast<std::uint8_t>(Command::start_stop_daq_list), 2};
    put_u16(select, static_cast<std::uint16_t>(list));
    auto selected = command(select, "START_STOP_DAQ_LIST");
    if (!selected) return Failure{selected.error()};
    const std::uint8_t first_pid = selected.value().size() > 1 ? selected.value()[1] : 0;
    for (std::size_t odt = 0; odt < odts[list].size(); ++odt) {
      std::size_t payload = 0;
      for (const DaqEntry& entry : odts[list][odt]) payload += entry.size;
      const std::size_t pid = first_pid + odt;
      if (odts_by_pid_.size() <= pid) odts_by_pid_.resize(pid + 1);
      odts_by_pid_[pid] = {list, odt == 0, odt + 1 == odts[list].size(), payload};
    }
  }
  samples_.clear();
  return run({static_cast<std::uint8_t>(Command::start_stop_synch), 1}, "START_STOP_SYNCH");
}

Status Master::stop_daq() {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::start_stop_synch), 0};
  auto response = command(request, "START_STOP_SYNCH");
  return response ? done() : Status{Failure{response.error()}};
}

Result<std::vector<DaqSample>> Master::receive_samples(std::chrono::milliseconds wait) {
  const auto deadline = std::chrono::steady_clock::now() + wait;
  while (samples_.empty()) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    auto received = channel_->receive(left.count() > 0 ? left : std::chrono::milliseconds{0});
    if (!received) return Failure{received.error()};
    if (!received.value()) break;
    take_asynchronous(std::move(*received.value()));
  }
  // And whatever else has arrived already, but no longer than asked: a flood of samples must not keep us here.
  while (std::chrono::steady_clock::now() < deadline) {
    auto received = channel_->receive(std::chrono::milliseconds{0});
    if (!received) return Failure{received.error()};
    if (!received.value()) break;
    take_asynchronous(std::move(*received.value()));
  }
  std::vector<DaqSample> samples(std::make_move_iterator(samples_.begin()), std::make_move_iterator(samples_.end()));
  samples_.clear();
  return samples;
}

}  // namespace duet::xcp::host
