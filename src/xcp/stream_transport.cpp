#include "duet/xcp/stream_transport.hpp"

namespace duet::xcp {

void StreamTransport::receive(std::span<const std::uint8_t> bytes) {
  decoder_.feed(bytes, [this](std::uint16_t, std::span<const std::uint8_t> command) {
    const std::span<const std::uint8_t> response = slave_.handle(command);
    if (response.empty()) return;
    (void)queue_.push(response.size() + TransmitQueue::record_header, 0,
                      [&](auto& out) { out.packet(response.size()).bytes(response.data(), response.size()); });
  });
}

std::size_t StreamTransport::transmit(std::span<std::uint8_t> out) {
  std::size_t written = 0;
  for (;;) {
    if (pending_ == 0) pending_ = queue_.pop(packet_);
    if (pending_ == 0) return written;
    const std::size_t size = write_frame(framing_, out.subspan(written), counter_, packet_.first(pending_));
    if (size == 0) return written;  // it does not fit now: keep it for the next call
    ++counter_;
    written += size;
    pending_ = 0;
  }
}

}  // namespace duet::xcp
