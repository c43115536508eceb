#include "duet/xcp/slave.hpp"

namespace duet::xcp {
namespace {

constexpr std::size_t index_of(Command command) { return static_cast<std::size_t>(command) - 0xC0U; }

}  // namespace

const std::array<Slave::CommandEntry, 0x40>& Slave::commands() {
  static constexpr std::array<CommandEntry, 0x40> table = [] {
    std::array<CommandEntry, 0x40> entries{};
    auto set = [&entries](Command command, Handler handler, std::uint8_t minimum_length, std::uint8_t resource = 0) {
      entries[index_of(command)] = {handler, minimum_length, resource};
    };
    set(Command::connect, &Slave::connect, 2);
    set(Command::disconnect, &Slave::disconnect, 1);
    set(Command::get_status, &Slave::get_status, 1);
    set(Command::synch, &Slave::synch, 1);
    set(Command::get_comm_mode_info, &Slave::get_comm_mode_info, 1);
    set(Command::get_id, &Slave::get_id, 2);
    set(Command::get_seed, &Slave::get_seed, 3);
    set(Command::unlock, &Slave::unlock, 2);
    set(Command::set_mta, &Slave::set_mta, 8);
    set(Command::upload, &Slave::upload, 2);
    set(Command::short_upload, &Slave::short_upload, 8);
    set(Command::build_checksum, &Slave::build_checksum, 8);
    set(Command::user_cmd, &Slave::user_cmd, 2);
    set(Command::download, &Slave::download, 2, resource::calibration_paging);
    set(Command::download_next, &Slave::download_next, 2, resource::calibration_paging);
    set(Command::download_max, &Slave::download_max, 1, resource::calibration_paging);
    set(Command::short_download, &Slave::short_download, 8, resource::calibration_paging);
    set(Command::modify_bits, &Slave::modify_bits, 6, resource::calibration_paging);
    constexpr std::uint8_t paging = resource::calibration_paging;
    set(Command::set_cal_page, &Slave::set_cal_page, 4, paging);
    set(Command::get_cal_page, &Slave::get_cal_page, 3, paging);
    set(Command::get_pag_processor_info, &Slave::get_pag_processor_info, 1, paging);
    set(Command::get_segment_info, &Slave::get_segment_info, 5, paging);
    set(Command::get_page_info, &Slave::get_page_info, 4, paging);
    set(Command::set_segment_mode, &Slave::set_segment_mode, 3, paging);
    set(Command::get_segment_mode, &Slave::get_segment_mode, 3, paging);
    set(Command::copy_cal_page, &Slave::copy_cal_page, 5, paging);
    constexpr std::uint8_t daq = resource::daq;
    set(Command::free_daq, &Slave::free_daq, 1, daq);
    set(Command::alloc_daq, &Slave::alloc_daq, 4, daq);
    set(Command::alloc_odt, &Slave::alloc_odt, 5, daq);
    set(Command::alloc_odt_entry, &Slave::alloc_odt_entry, 6, daq);
    set(Command::set_daq_ptr, &Slave::set_daq_ptr, 6, daq);
    set(Command::write_daq, &Slave::write_daq, 8, daq);
    set(Command::write_daq_multiple, &Slave::write_daq_multiple, 2, daq);
    set(Command::read_daq, &Slave::read_daq, 1, daq);
    set(Command::clear_daq_list, &Slave::clear_daq_list, 4, daq);
    set(Command::set_daq_list_mode, &Slave::set_daq_list_mode, 8, daq);
    set(Command::get_daq_list_mode, &Slave::get_daq_list_mode, 4, daq);
    set(Command::start_stop_daq_list, &Slave::start_stop_daq_list, 4, daq);
    set(Command::start_stop_synch, &Slave::start_stop_synch, 2, daq);
    set(Command::get_daq_clock, &Slave::get_daq_clock, 1);
    set(Command::get_daq_processor_info, &Slave::get_daq_processor_info, 1);
    set(Command::get_daq_resolution_info, &Slave::get_daq_resolution_info, 1);
    set(Command::get_daq_event_info, &Slave::get_daq_event_info, 4);
    set(Command::get_daq_list_info, &Slave::get_daq_list_info, 4);
    return entries;
  }();
  return table;
}

std::span<const std::uint8_t> Slave::handle(std::span<const std::uint8_t> command) {
  if (command.empty()) return {};
  const std::uint8_t code = command[0];
  // A disconnected slave answers nothing but CONNECT.
  if (!connected_ && code != static_cast<std::uint8_t>(Command::connect)) return {};
  // Any other command ends a DOWNLOAD sequence in progress; what it collected is dropped, never half written.
  if (code != static_cast<std::uint8_t>(Command::download_next)) download_remaining_ = 0;

  const std::size_t packet_limit = configuration_.max_cto < max_packet ? configuration_.max_cto : max_packet;
  PacketWriter payload{std::span{response_}.subspan(1, packet_limit - 1), configuration_.byte_order};
  Result result = fail(Error::cmd_unknown);
  if (code >= 0xC0) {
    const CommandEntry& entry = commands()[code - 0xC0U];
    if (entry.handler == nullptr) {
      result = fail(Error::cmd_unknown);
    } else if (command.size() < entry.minimum_length) {
      result = fail(Error::cmd_syntax);
    } else if ((entry.resource & locked_) != 0) {
      result = fail(Error::access_locked);
    } else {
      PacketReader request{command, configuration_.byte_order};
      request.skip(1);
      result = (this->*entry.handler)(request, payload);
    }
  }

  switch (result.outcome) {
    case Outcome::silent: return {};
    case Outcome::positive: response_[0] = pid::response; return std::span{response_}.first(1 + payload.size());
    case Outcome::negative: break;
  }
  // FE, the error code, then whatever the handler wrote (an expected count, a limit).
  std::size_t size = payload.size() + 2 <= packet_limit ? payload.size() : packet_limit - 2;
  for (std::size_t byte = size; byte > 0; --byte) response_[byte + 1] = response_[byte];
  response_[0] = pid::error;
  response_[1] = static_cast<std::uint8_t>(result.error);
  return std::span{response_}.first(size + 2);
}

Slave::Result Slave::read_at_mta(std::uint32_t count, PacketWriter& response) {
  if (mta_.points_to_identification) {
    const std::span<const std::uint8_t> source = mta_.identification;
    if (count > source.size()) return fail(Error::access_denied);
    response.bytes(source.first(count));
    mta_.identification = source.subspan(count);
    return ok;
  }
  const std::uint8_t* source = readable_memory(mta_.extension, mta_.address, count);
  if (source == nullptr) return fail(Error::access_denied);
  response.bytes({source, count});
  mta_.address += count;
  return ok;
}

Slave::Result Slave::write_at_mta(std::span<const std::uint8_t> bytes) {
  if (mta_.points_to_identification) return fail(Error::access_denied);
  const auto count = static_cast<std::uint32_t>(bytes.size());
  std::uint8_t* destination = writable_memory(mta_.extension, mta_.address, count);
  if (destination == nullptr) return fail(Error::access_denied);
  write_memory(destination, bytes);
  mta_.address += count;
  return ok;
}

const CalibrationSegment* Slave::segment_at(std::uint8_t extension, std::uint32_t address, std::uint32_t size,
                                            std::size_t& index) const {
  for (index = 0; index < configuration_.segments.size() && index < max_segments; ++index) {
    const CalibrationSegment& segment = configuration_.segments[index];
    if (segment.extension != extension || address < segment.address) continue;
    const std::uint32_t offset = address - segment.address;
    if (offset <= segment.size && size <= segment.size - offset) return &segment;
  }
  return nullptr;
}

const std::uint8_t* Slave::readable_memory(std::uint8_t extension, std::uint32_t address, std::uint32_t size) const {
  std::size_t index = 0;
  if (const CalibrationSegment* segment = segment_at(extension, address, size, index)) {
    const std::uint32_t offset = address - segment->address;
    return xcp_page_[index] == working_page ? segment->working + offset : segment->reference + offset;
  }
  return configuration_.memory.find(extension, address, size, Access::read_only);
}

// The reference page is never writable: writes there are refused like writes to read-only memory.
std::uint8_t* Slave::writable_memory(std::uint8_t extension, std::uint32_t address, std::uint32_t size) const {
  std::size_t index = 0;
  if (const CalibrationSegment* segment = segment_at(extension, address, size, index)) {
    return xcp_page_[index] == working_page ? segment->working + (address - segment->address) : nullptr;
  }
  return configuration_.memory.find(extension, address, size, Access::read_write);
}

void Slave::write_memory(std::uint8_t* destination, std::span<const std::uint8_t> bytes) const {
  if (configuration_.write_atomically != nullptr) {
    configuration_.write_atomically(destination, bytes);
  } else {
    for (std::size_t byte = 0; byte < bytes.size(); ++byte) destination[byte] = bytes[byte];
  }
}

void Slave::reset_session() {
  stop_all_daq();
  xcp_page_.fill(working_page);
  mta_ = {};
  seed_length_ = 0;
  seed_sent_ = 0;
  key_length_ = 0;
  key_received_ = 0;
  download_remaining_ = 0;
  download_collected_ = 0;
}

}  // namespace duet::xcp
