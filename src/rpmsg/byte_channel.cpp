#include "duet/rpmsg/byte_channel.hpp"

namespace duet::rpmsg {

void ByteChannel::received(void* context, std::span<const std::uint8_t> payload) {
  auto& channel = *static_cast<ByteChannel*>(context);
  channel.bytes_received_ += static_cast<std::uint32_t>(payload.size());
  channel.receive_(channel.protocol_, payload);
}

void ByteChannel::pump(Device& device, Endpoint& endpoint) {
  for (;;) {  // bounded: each turn sends a message or ends; the protocol's queue is finite
    if (held_ == 0) {
      held_ = transmit_(protocol_, message_);
      if (held_ == 0) return;
    }
    const auto message = std::span<const std::uint8_t>{message_.data(), held_};
    switch (device.send(endpoint, message)) {
      case SendResult::sent: bytes_sent_ += static_cast<std::uint32_t>(held_); break;
      case SendResult::no_remote_yet:
      case SendResult::too_long:  // cannot happen: message_ holds one payload at most
        bytes_dropped_ += static_cast<std::uint32_t>(held_);
        break;
      case SendResult::no_buffer: ++waits_; return;
    }
    held_ = 0;
  }
}

}  // namespace duet::rpmsg
