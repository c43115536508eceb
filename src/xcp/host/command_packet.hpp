#pragma once
// A command packet for the master to send: the command code, then fields in the slave's byte order.

#include <cstdint>
#include <span>
#include <vector>

#include "duet/xcp/packet.hpp"
#include "duet/xcp/protocol.hpp"

namespace duet::xcp::host {

class CommandPacket : public OrderedFieldWriter<CommandPacket> {
 public:
  CommandPacket(Command command, ByteOrder order) : order_(order) {
    bytes_.push_back(static_cast<std::uint8_t>(command));
  }

  CommandPacket& u8(std::uint8_t value) {
    bytes_.push_back(value);
    return *this;
  }
  [[nodiscard]] ByteOrder order() const { return order_; }
  CommandPacket& bytes(std::span<const std::uint8_t> values) {
    bytes_.insert(bytes_.end(), values.begin(), values.end());
    return *this;
  }

  [[nodiscard]] std::span<const std::uint8_t> packet() const { return bytes_; }

 private:
  ByteOrder order_;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace duet::xcp::host
