// The master's DAQ: what the slave's DAQ processor is like, lists set up as daq_plan.hpp lays them out, and packets
// read back into samples by the slave's identification field, timestamp size and byte order. A packet that cannot
// be used is counted (PacketCounters), never silently dropped.

#include <algorithm>

#include "command_packet.hpp"
#include "daq_plan.hpp"
#include "duet/xcp/host/master.hpp"
#include "duet/xcp/protocol.hpp"

namespace duet::xcp::host {
namespace {

// DAQ_KEY_BYTE.
constexpr unsigned identification_shift = 6;
constexpr unsigned address_extension_shift = 4;
// TIMESTAMP_MODE.
constexpr std::uint8_t timestamp_size_bits = 0x07;
constexpr std::uint8_t timestamp_fixed_bit = 0x08;
constexpr unsigned timestamp_unit_shift = 4;
constexpr std::uint8_t pid_overload_bit = 0x80;
// SET_DAQ_LIST_MODE and START_STOP_DAQ_LIST / START_STOP_SYNCH modes.
constexpr std::uint8_t timestamped_mode = 0x10;
constexpr std::uint8_t select = 2;
constexpr std::uint8_t start_selected = 1;
constexpr std::uint8_t stop_all = 0;

}  // namespace

Result<DaqProcessor> Master::read_daq_processor() {
  const ByteOrder order = properties_.byte_order;
  const std::vector<std::uint8_t> processor_request{static_cast<std::uint8_t>(Command::get_daq_processor_info)};
  auto processor = command(processor_request, "GET_DAQ_PROCESSOR_INFO");
  if (!processor) return Failure{processor.error()};
  if (processor.value().size() < 8) return Failure{"GET_DAQ_PROCESSOR_INFO: the response is too short"};
  const std::vector<std::uint8_t> resolution_request{static_cast<std::uint8_t>(Command::get_daq_resolution_info)};
  auto resolution = command(resolution_request, "GET_DAQ_RESOLUTION_INFO");
  if (!resolution) return Failure{resolution.error()};
  if (resolution.value().size() < 8) return Failure{"GET_DAQ_RESOLUTION_INFO: the response is too short"};

  DaqProcessor daq;
  PacketReader info{processor.value(), order};
  info.skip(1);
  daq.properties = info.u8();
  daq.max_daq = info.u16();
  daq.max_event_channel = info.u16();
  daq.min_daq = info.u8();
  const std::uint8_t key_byte = info.u8();
  daq.identification = static_cast<IdentificationField>(key_byte >> identification_shift);
  daq.address_extension = static_cast<std::uint8_t>((key_byte >> address_extension_shift) & 0x03U);
  PacketReader sizes{resolution.value(), order};
  sizes.skip(1);
  daq.granularity = sizes.u8();
  daq.max_entry_size = sizes.u8();
  sizes.skip(2);  // STIM
  const std::uint8_t timestamp_mode = sizes.u8();
  daq.timestamp_ticks = sizes.u16();
  daq.timestamp_size = static_cast<std::uint8_t>(timestamp_mode & timestamp_size_bits);
  daq.timestamp_fixed = (timestamp_mode & timestamp_fixed_bit) != 0;
  daq.timestamp_unit = static_cast<std::uint8_t>(timestamp_mode >> timestamp_unit_shift);
  if (daq.timestamp_size != 0 && daq.timestamp_size != 1 && daq.timestamp_size != 2 && daq.timestamp_size != 4) {
    return Failure{"GET_DAQ_RESOLUTION_INFO: a timestamp of " + std::to_string(daq.timestamp_size) +
                   " bytes is none of 1, 2 or 4"};
  }
  daq_processor_ = daq;
  return daq;
}

Status Master::start_daq(const std::vector<DaqListSetup>& lists) {
  if (!daq_processor_) {
    if (auto read = read_daq_processor(); !read) return Failure{read.error()};
  }
  auto plan = plan_daq(lists, *daq_processor_, properties_.max_dto);
  if (!plan) return Failure{"DAQ: " + plan.error()};
  const ByteOrder order = properties_.byte_order;
  auto run = [this](const CommandPacket& request, std::string_view name) -> Status {
    auto response = command(request.packet(), name);
    return response ? done() : Status{Failure{response.error()}};
  };
  if (Status freed = run(CommandPacket{Command::free_daq, order}, "FREE_DAQ"); !freed) return freed;
  const auto count = static_cast<std::uint16_t>(plan.value().lists.size());
  if (Status allocated = run(CommandPacket{Command::alloc_daq, order}.u8(0).u16(count), "ALLOC_DAQ"); !allocated) {
    return allocated;
  }
  for (const PlannedList& list : plan.value().lists) {
    const auto odts = static_cast<std::uint8_t>(list.odts.size());
    const CommandPacket request = CommandPacket{Command::alloc_odt, order}.u8(0).u16(list.number).u8(odts);
    if (Status allocated = run(request, "ALLOC_ODT"); !allocated) return allocated;
  }
  for (const PlannedList& list : plan.value().lists) {
    for (std::size_t odt = 0; odt < list.odts.size(); ++odt) {
      const CommandPacket request = CommandPacket{Command::alloc_odt_entry, order}
                                        .u8(0)
                                        .u16(list.number)
                                        .u8(static_cast<std::uint8_t>(odt))
                                        .u8(static_cast<std::uint8_t>(list.odts[odt].entries.size()));
      if (Status allocated = run(request, "ALLOC_ODT_ENTRY"); !allocated) return allocated;
    }
  }
  layouts_.assign(lists.size(), {});
  by_pid_.clear();
  assemblies_.assign(lists.size(), {});
  timestamps_ = plan.value().timestamps;
  for (std::size_t index = 0; index < plan.value().lists.size(); ++index) {
    const PlannedList& list = plan.value().lists[index];
    for (std::size_t odt = 0; odt < list.odts.size(); ++odt) {
      const CommandPacket pointer =
          CommandPacket{Command::set_daq_ptr, order}.u8(0).u16(list.number).u8(static_cast<std::uint8_t>(odt)).u8(0);
      if (Status set = run(pointer, "SET_DAQ_PTR"); !set) return set;
      for (const DaqEntry& entry : list.odts[odt].entries) {
        const CommandPacket write =
            CommandPacket{Command::write_daq, order}.u8(0xFF).u8(entry.size).u8(entry.extension).u32(entry.address);
        if (Status written = run(write, "WRITE_DAQ"); !written) return written;
      }
      layouts_[index].push_back({index, odt, odt + 1 == list.odts.size(), list.odts[odt].payload});
    }
    const CommandPacket mode = CommandPacket{Command::set_daq_list_mode, order}
                                   .u8(timestamps_ ? timestamped_mode : 0)
                                   .u16(list.number)
                                   .u16(list.event)
                                   .u8(list.prescaler)
                                   .u8(0);
    if (Status set = run(mode, "SET_DAQ_LIST_MODE"); !set) return set;
    const CommandPacket selection = CommandPacket{Command::start_stop_daq_list, order}.u8(select).u16(list.number);
    auto selected = command(selection.packet(), "START_STOP_DAQ_LIST");
    if (!selected) return Failure{selected.error()};
    if (selected.value().size() < 2) return Failure{"START_STOP_DAQ_LIST: the response is too short"};
    if (daq_processor_->identification == IdentificationField::absolute) {
      const std::size_t first_pid = selected.value()[1];
      for (const OdtLayout& odt : layouts_[index]) {
        const std::size_t pid = first_pid + odt.odt;
        if (by_pid_.size() <= pid) by_pid_.resize(pid + 1);
        by_pid_[pid] = odt;
      }
    }
  }
  samples_.clear();
  last_timestamp_.reset();
  return run(CommandPacket{Command::start_stop_synch, order}.u8(start_selected), "START_STOP_SYNCH");
}

Status Master::stop_daq() {
  const std::vector<std::uint8_t> request{static_cast<std::uint8_t>(Command::start_stop_synch), stop_all};
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

void Master::take_asynchronous(std::vector<std::uint8_t> packet) {
  const std::uint8_t pid = packet[0];
  if (pid == pid::event) {
    if (packet.size() < 2) {
      ++counters_.too_short;
    } else if (packet[1] == static_cast<std::uint8_t>(EventCode::daq_overload)) {
      ++counters_.overload_events;
    }
    return;
  }
  if (pid >= pid::service) {  // a service request, or an answer to no command waiting
    ++counters_.unexpected;
    return;
  }
  take_daq(packet);
}

const Master::OdtLayout* Master::odt_of(std::span<const std::uint8_t> packet, std::uint8_t odt_number) const {
  const IdentificationField field = daq_processor_->identification;
  if (field == IdentificationField::absolute) {
    return odt_number < by_pid_.size() && by_pid_[odt_number] ? &*by_pid_[odt_number] : nullptr;
  }
  PacketReader reader{packet, properties_.byte_order};
  reader.skip(field == IdentificationField::relative_word_aligned ? 2 : 1);
  const std::uint16_t number = field == IdentificationField::relative_byte ? reader.u8() : reader.u16();
  if (number < daq_processor_->min_daq) return nullptr;
  const std::size_t list = number - daq_processor_->min_daq;
  return list < layouts_.size() && odt_number < layouts_[list].size() ? &layouts_[list][odt_number] : nullptr;
}

std::int64_t Master::unwrap(std::uint32_t timestamp) {
  const unsigned bits = 8U * daq_processor_->timestamp_size;
  const std::uint64_t range = std::uint64_t{1} << bits;
  if (last_timestamp_) {
    // The step from the last sample, taken as the shorter way round: samples of different lists may come a little
    // out of order.
    const std::uint64_t step = (timestamp - *last_timestamp_) & (range - 1);
    ticks_ += step < range / 2 ? static_cast<std::int64_t>(step)
                               : static_cast<std::int64_t>(step) - static_cast<std::int64_t>(range);
  } else {
    ticks_ = timestamp;
  }
  last_timestamp_ = timestamp;
  return ticks_;
}

void Master::abandon(std::size_t list) {
  Assembly& assembly = assemblies_[list];
  if (deliver_incomplete_ && assembly.started) samples_.push_back({list, assembly.ticks, {}, false});
  assembly = {};
}

void Master::take_daq(std::span<const std::uint8_t> packet) {
  if (!daq_processor_ || layouts_.empty()) {
    ++counters_.unknown_identification;
    return;
  }
  const DaqProcessor& daq = *daq_processor_;
  const std::size_t header = identification_size(daq.identification);
  if (packet.size() < header) {
    ++counters_.too_short;
    return;
  }
  std::uint8_t odt_number = packet[0];
  if (daq.overload_indication() == OverloadIndication::pid_msb && (odt_number & pid_overload_bit) != 0) {
    ++counters_.overload_events;
    odt_number = static_cast<std::uint8_t>(odt_number & ~pid_overload_bit);
  }
  const OdtLayout* odt = odt_of(packet, odt_number);
  if (odt == nullptr) {
    ++counters_.unknown_identification;
    return;
  }
  Assembly& assembly = assemblies_[odt->list];
  const bool first = odt->odt == 0;
  const std::size_t stamp = first && timestamps_ ? daq.timestamp_size : 0U;
  if (!first && (!assembly.started || assembly.next_odt != odt->odt)) {  // its sample's earlier ODTs are missing
    counters_.incomplete += assembly.packets + 1;
    abandon(odt->list);
    return;
  }
  if (first && assembly.started) {  // the last sample never ended
    counters_.incomplete += assembly.packets;
    abandon(odt->list);
  }
  if (packet.size() < header + stamp + odt->payload) {
    ++counters_.too_short;
    counters_.incomplete += first ? 0 : assembly.packets;
    abandon(odt->list);
    return;
  }
  if (packet.size() > header + stamp + odt->payload) ++counters_.padded;
  if (first) {
    assembly = {.started = true, .next_odt = 0, .packets = 0, .ticks = 0, .bytes = {}};
    if (stamp != 0) {
      PacketReader reader{packet, properties_.byte_order};
      reader.skip(header);
      const std::uint32_t timestamp = stamp == 1 ? reader.u8() : stamp == 2 ? reader.u16() : reader.u32();
      assembly.ticks = unwrap(timestamp);
    }
  }
  const auto payload = packet.subspan(header + stamp, odt->payload);
  assembly.bytes.insert(assembly.bytes.end(), payload.begin(), payload.end());
  ++assembly.next_odt;
  ++assembly.packets;
  if (odt->last) {
    samples_.push_back({odt->list, assembly.ticks, std::move(assembly.bytes)});
    assembly = {};
  }
}

}  // namespace duet::xcp::host
