#include "duet/xcp/transmit_queue.hpp"

namespace duet::xcp {

std::size_t TransmitQueue::pop(std::span<std::uint8_t> packet) {
  const std::size_t tail = tail_.load(std::memory_order_relaxed);
  if (load_acquire(head_) == tail) return 0;
  const std::size_t size_of_ring = ring_.size();
  const auto byte_at = [&](std::size_t offset) { return ring_[(tail + offset) % size_of_ring]; };
  const std::size_t size = static_cast<std::size_t>(byte_at(0)) | (static_cast<std::size_t>(byte_at(1)) << 8U);
  const bool fits = size <= packet.size();
  if (fits) {
    for (std::size_t byte = 0; byte < size; ++byte) packet[byte] = byte_at(record_header + byte);
  }
  store_release(tail_, tail + record_header + size);
  return fits ? size : 0;
}

}  // namespace duet::xcp
