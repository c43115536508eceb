// The slave's calibration commands. Each command's bytes reach the model's memory in one atomic write (see
// SlaveConfiguration::write_atomically); a DOWNLOAD sequence is collected first and written at its end.

#include "duet/xcp/slave.hpp"

namespace duet::xcp {

Slave::Result Slave::download(PacketReader& request, PacketWriter&) {
  const std::uint8_t count = request.u8();
  if (count == 0) return fail(Error::out_of_range);
  const std::size_t room = static_cast<std::size_t>(configuration_.max_cto) - 2U;
  if (count <= room) {
    const std::span<const std::uint8_t> data = request.bytes(count);
    if (data.size() != count) return fail(Error::cmd_syntax);
    return write_at_mta(data);
  }
  // The first packet of a sequence that DOWNLOAD_NEXT completes (master block mode).
  if (count > configuration_.download_buffer.size()) return fail(Error::out_of_range);
  if (mta_.points_to_identification || writable_memory(mta_.extension, mta_.address, count) == nullptr) {
    return fail(Error::access_denied);
  }
  const std::span<const std::uint8_t> data = request.bytes(room);
  if (data.size() != room) return fail(Error::cmd_syntax);
  for (std::size_t byte = 0; byte < room; ++byte) configuration_.download_buffer[byte] = data[byte];
  download_collected_ = room;
  download_remaining_ = count - static_cast<std::uint32_t>(room);
  return silent;
}

Slave::Result Slave::download_next(PacketReader& request, PacketWriter& response) {
  const std::uint8_t count = request.u8();
  if (download_remaining_ == 0 || count != download_remaining_) {
    response.u8(static_cast<std::uint8_t>(download_remaining_));  // the number the slave expected
    download_remaining_ = 0;
    return fail(Error::sequence);
  }
  const std::size_t room = static_cast<std::size_t>(configuration_.max_cto) - 2U;
  const std::size_t part = count < room ? count : room;
  const std::span<const std::uint8_t> data = request.bytes(part);
  if (data.size() != part) {
    download_remaining_ = 0;
    return fail(Error::cmd_syntax);
  }
  for (std::uint8_t byte : data) configuration_.download_buffer[download_collected_++] = byte;
  download_remaining_ -= static_cast<std::uint32_t>(part);
  if (download_remaining_ != 0) return silent;
  return write_at_mta(configuration_.download_buffer.first(download_collected_));
}

Slave::Result Slave::download_max(PacketReader& request, PacketWriter&) {
  const std::size_t count = static_cast<std::size_t>(configuration_.max_cto) - 1U;
  const std::span<const std::uint8_t> data = request.bytes(count);
  if (data.size() != count) return fail(Error::cmd_syntax);
  return write_at_mta(data);
}

Slave::Result Slave::short_download(PacketReader& request, PacketWriter&) {
  const std::uint8_t count = request.u8();
  request.skip(1);
  const std::uint8_t extension = request.u8();
  const std::uint32_t address = request.u32();
  if (count == 0 || count > configuration_.max_cto - 8U) return fail(Error::out_of_range);
  const std::span<const std::uint8_t> data = request.bytes(count);
  if (data.size() != count) return fail(Error::cmd_syntax);
  mta_ = {.extension = extension, .address = address};
  return write_at_mta(data);
}

// The 32-bit value at the MTA becomes (value & ~(~and_mask << shift)) ^ (xor_mask << shift); the MTA stays.
Slave::Result Slave::modify_bits(PacketReader& request, PacketWriter&) {
  const std::uint8_t shift = request.u8();
  const std::uint16_t and_mask = request.u16();
  const std::uint16_t xor_mask = request.u16();
  if (shift > 16) return fail(Error::out_of_range);  // the masks must stay inside the 32 bits
  if (mta_.points_to_identification) return fail(Error::access_denied);
  std::uint8_t* target = writable_memory(mta_.extension, mta_.address, 4);
  if (target == nullptr) return fail(Error::access_denied);
  std::uint32_t value = 0;
  for (std::size_t byte = 0; byte < 4; ++byte) value |= static_cast<std::uint32_t>(target[byte]) << (8U * byte);
  const std::uint32_t cleared = static_cast<std::uint32_t>(static_cast<std::uint16_t>(~and_mask)) << shift;
  value = (value & ~cleared) ^ (static_cast<std::uint32_t>(xor_mask) << shift);
  const std::array<std::uint8_t, 4> bytes{static_cast<std::uint8_t>(value), static_cast<std::uint8_t>(value >> 8U),
                                          static_cast<std::uint8_t>(value >> 16U),
                                          static_cast<std::uint8_t>(value >> 24U)};
  write_memory(target, bytes);
  return ok;
}

}  // namespace duet::xcp
