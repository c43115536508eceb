// The slave's standard commands: session, identification, protection, memory transfer address, upload, checksum.

#include "duet/xcp/slave.hpp"

namespace duet::xcp {
namespace {

// COMM_MODE_BASIC: byte address granularity, no slave block mode, GET_COMM_MODE_INFO available; bit 0 is the byte
// order (1 = Motorola).
constexpr std::uint8_t comm_mode_optional_available = 0x80;
constexpr std::uint8_t comm_mode_motorola = 0x01;
// COMM_MODE_OPTIONAL: master block mode (DOWNLOAD_NEXT sequences).
constexpr std::uint8_t master_block_mode = 0x01;
constexpr std::uint8_t driver_version = 0x10;  // 1.0, in nibbles
constexpr std::uint8_t protectable =
    resource::calibration_paging | resource::daq | resource::stim | resource::programming;

// GET_ID's identification types (XCP protocol layer, GET_ID: 0 ASCII text, 1 the A2L file's name, ...).
constexpr std::uint8_t id_ascii_text = 0;
constexpr std::uint8_t id_a2l_name = 1;
constexpr std::uint8_t id_a2l_file = 4;
constexpr std::uint8_t id_epk = 5;
// GET_ID's mode byte, bit 0: the identification follows in this response (else the master uploads it from the MTA).
constexpr std::uint8_t id_in_response = 0x01;
constexpr std::size_t id_response_header = 8;  // PID, mode, reserved word, length

std::span<const std::uint8_t> as_bytes(std::string_view text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

bool is_one_resource(std::uint8_t resource) {
  return resource != 0 && (resource & (resource - 1U)) == 0 && (resource & protectable) == resource;
}

}  // namespace

Slave::Result Slave::connect(PacketReader& request, PacketWriter& response) {
  const std::uint8_t mode = request.u8();
  if (mode > 1) return fail(Error::out_of_range);  // 0 normal, 1 user defined
  connected_ = true;
  locked_ = configuration_.protected_resources;
  reset_session();
  const bool usual_daq_layout = configuration_.identification_field == IdentificationField::absolute &&
                                configuration_.timestamp_size == TimestampSize::dword &&
                                configuration_.byte_order == ByteOrder::intel;
  sample_.store(configuration_.queue == nullptr ? sample_nothing
                : usual_daq_layout              ? sample_in_usual_layout
                                                : sample_in_other_layout,
                std::memory_order_relaxed);
  const bool has_daq = !configuration_.daq.lists.empty() && configuration_.queue != nullptr;
  const auto resources = static_cast<std::uint8_t>(resource::calibration_paging | (has_daq ? resource::daq : 0U));
  const std::uint8_t comm_mode_basic =
      comm_mode_optional_available | (configuration_.byte_order == ByteOrder::motorola ? comm_mode_motorola : 0U);
  response.u8(resources).u8(comm_mode_basic).u8(configuration_.max_cto);
  response.u16(configuration_.max_dto).u8(protocol_layer_version).u8(transport_layer_version);
  return ok;
}

Slave::Result Slave::disconnect(PacketReader&, PacketWriter&) {
  connected_ = false;
  reset_session();
  return ok;
}

Slave::Result Slave::get_status(PacketReader&, PacketWriter& response) {
  // Session status, resource protection, state number (reserved before 1.4), session configuration id.
  constexpr std::uint8_t daq_running_status = 0x40;
  response.u8(daq_running() ? daq_running_status : 0).u8(locked_).u8(0).u16(0);
  return ok;
}

Slave::Result Slave::synch(PacketReader&, PacketWriter&) { return fail(Error::cmd_synch); }

Slave::Result Slave::get_comm_mode_info(PacketReader&, PacketWriter& response) {
  // Reserved, COMM_MODE_OPTIONAL, reserved, MAX_BS, MIN_ST, QUEUE_SIZE, driver version.
  response.u8(0).u8(master_block_mode).u8(0).u8(max_block_size).u8(0).u8(0).u8(driver_version);
  return ok;
}

// The identification is uploaded through the MTA (mode 0), as the standard's masters expect for the A2L file, or
// for the short ones, if the firmware chooses, sent in the response itself (mode 1). An identification the firmware
// does not have has length 0.
Slave::Result Slave::get_id(PacketReader& request, PacketWriter& response) {
  const std::uint8_t type = request.u8();
  std::span<const std::uint8_t> identification;
  const bool short_text = type == id_ascii_text || type == id_a2l_name;
  if (short_text) identification = as_bytes(configuration_.identification);
  if (type == id_a2l_file) identification = configuration_.a2l;
  if (type == id_epk) identification = as_bytes(configuration_.epk);
  const auto length = static_cast<std::uint32_t>(identification.size());
  if (short_text && configuration_.identification_in_response &&
      id_response_header + identification.size() <= configuration_.max_cto) {
    response.u8(id_in_response).u16(0).u32(length).bytes(identification);
    return ok;
  }
  mta_ = {.identification = identification, .points_to_identification = true};
  response.u8(0).u16(0).u32(length);
  return ok;
}

Slave::Result Slave::get_seed(PacketReader& request, PacketWriter& response) {
  const std::uint8_t mode = request.u8();
  const std::uint8_t requested = request.u8();
  if (mode == 0) {
    if (!is_one_resource(requested)) return fail(Error::out_of_range);
    key_received_ = 0;
    key_length_ = 0;
    if ((locked_ & requested) == 0) {  // not protected: a seed of length 0
      seed_length_ = 0;
      response.u8(0);
      return ok;
    }
    const SeedAndKey& seed_and_key = configuration_.seed_and_key;
    if (seed_and_key.make_seed == nullptr || seed_and_key.key_is_valid == nullptr) return fail(Error::generic);
    seed_resource_ = requested;
    seed_length_ = seed_and_key.make_seed(requested, seed_);
    if (seed_length_ == 0 || seed_length_ > seed_.size()) return fail(Error::generic);
    seed_sent_ = 0;
  } else if (mode != 1) {
    return fail(Error::out_of_range);
  } else if (seed_length_ == 0 || seed_sent_ >= seed_length_) {
    return fail(Error::sequence);  // no seed is being sent
  }
  const std::size_t remaining = seed_length_ - seed_sent_;
  const std::size_t room = static_cast<std::size_t>(configuration_.max_cto) - 2U;
  const std::size_t part = remaining < room ? remaining : room;
  response.u8(static_cast<std::uint8_t>(remaining)).bytes(std::span{seed_}.subspan(seed_sent_, part));
  seed_sent_ += part;
  return ok;
}

Slave::Result Slave::unlock(PacketReader& request, PacketWriter& response) {
  const std::uint8_t remaining = request.u8();
  if (seed_length_ == 0 || seed_sent_ < seed_length_) return fail(Error::sequence);  // ask for the whole seed first
  if (key_received_ == 0) {
    if (remaining == 0 || remaining > key_.size()) return fail(Error::out_of_range);
    key_length_ = remaining;
  } else if (remaining != key_length_ - key_received_) {
    return fail(Error::sequence);
  }
  const std::size_t room = static_cast<std::size_t>(configuration_.max_cto) - 2U;
  const std::size_t part = remaining < room ? remaining : room;
  const std::span<const std::uint8_t> key_part = request.bytes(part);
  if (key_part.size() != part) return fail(Error::cmd_syntax);
  for (std::uint8_t byte : key_part) key_[key_received_++] = byte;
  if (key_received_ == key_length_) {
    const bool valid = configuration_.seed_and_key.key_is_valid(seed_resource_, std::span{seed_}.first(seed_length_),
                                                                std::span{key_}.first(key_length_));
    seed_length_ = 0;
    key_received_ = 0;
    if (!valid) {  // a wrong key ends the session, as the standard asks
      connected_ = false;
      return fail(Error::access_locked);
    }
    locked_ = static_cast<std::uint8_t>(locked_ & ~seed_resource_);
  }
  response.u8(locked_);
  return ok;
}

Slave::Result Slave::set_mta(PacketReader& request, PacketWriter&) {
  request.skip(2);
  const std::uint8_t extension = request.u8();
  mta_ = {.extension = extension, .address = request.u32()};
  return ok;
}

Slave::Result Slave::upload(PacketReader& request, PacketWriter& response) {
  const std::uint8_t count = request.u8();
  if (count == 0 || count > configuration_.max_cto - 1U) return fail(Error::out_of_range);  // no slave block mode
  return read_at_mta(count, response);
}

Slave::Result Slave::short_upload(PacketReader& request, PacketWriter& response) {
  const std::uint8_t count = request.u8();
  request.skip(1);
  const std::uint8_t extension = request.u8();
  const std::uint32_t address = request.u32();
  if (count == 0 || count > configuration_.max_cto - 1U) return fail(Error::out_of_range);
  mta_ = {.extension = extension, .address = address};
  return read_at_mta(count, response);
}

Slave::Result Slave::build_checksum(PacketReader& request, PacketWriter& response) {
  request.skip(3);
  const std::uint32_t size = request.u32();
  const ChecksumType type = configuration_.checksum_type;
  const std::uint16_t granule = type == ChecksumType::add_44                                   ? 4U
                                : type == ChecksumType::add_22 || type == ChecksumType::add_24 ? 2U
                                                                                               : 1U;
  if (mta_.points_to_identification) return fail(Error::access_denied);
  if (size == 0 || size > configuration_.max_checksum_block || size % granule != 0 || mta_.address % granule != 0) {
    // The negative response's layout: MTA_BLOCK_SIZE_ALIGN (word) at byte 2, the largest block the slave accepts
    // (dword) at byte 4, where the positive response has the checksum.
    response.u16(granule).u32(configuration_.max_checksum_block);
    return fail(Error::out_of_range);
  }
  const std::uint8_t* block = readable_memory(mta_.extension, mta_.address, size);
  if (block == nullptr) return fail(Error::access_denied);
  mta_.address += size;
  response.u8(static_cast<std::uint8_t>(type)).u8(0).u8(0).u32(checksum(type, {block, size}));
  return ok;
}

// NOLINTNEXTLINE(readability-make-member-function-const): every handler has the table's signature
Slave::Result Slave::user_cmd(PacketReader& request, PacketWriter& response) {
  if (configuration_.user_command == nullptr) return fail(Error::cmd_unknown);
  Error error = Error::generic;
  return configuration_.user_command(request, response, error) ? ok : fail(error);
}

}  // namespace duet::xcp
