#include "duet/xcp/stream_transport.hpp"

namespace duet::xcp {

void StreamTransport::receive(std::span<const std::uint8_t> bytes) {
  decoder_.feed(bytes, [this](std::uint16_t, std::span<const std::uint8_t> command) {
    const std::span<const std::uint8_t> response = slave_.handle(command);
    if (response.empty()) return;
    const bool queued = queue_.push(response.size() + TransmitQueue::record_header, 0, [&](auto& out) {
      out.packet(response.size()).bytes(response.data(), response.size());
    });
    if (!queued) responses_dropped_.fetch_add(1, std::memory_order_relaxed);
  });
}

std::size_t StreamTransport::transmit(std::span<std::uint8_t> out) {
  return framer_.transmit(out, [this](std::span<std::uint8_t> packet) { return queue_.pop(packet); });
}

}  // namespace duet::xcp
