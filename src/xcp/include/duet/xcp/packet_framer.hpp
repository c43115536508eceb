#pragma once
// Frames outgoing packets into a byte stream, numbering them: the sending half of a stream transport. A packet taken
// from its source that does not fit the caller's buffer waits in `packet_buffer` for the next call, so nothing is lost
// and nothing is sent in part. Freestanding.

#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/xcp/framing.hpp"

namespace duet::xcp {

class PacketFramer {
 public:
  // `packet_buffer` holds the largest packet the source gives.
  PacketFramer(const Framing& framing, std::span<std::uint8_t> packet_buffer)
      : framing_(framing), packet_(packet_buffer) {}

  // Frames packets into `out` as far as whole frames fit; `next_packet(buffer)` writes the next packet into buffer and
  // returns its size, 0 when there is none. Returns the bytes written to `out` (0: nothing to send).
  template <typename NextPacket>
  std::size_t transmit(std::span<std::uint8_t> out, NextPacket&& next_packet) {
    std::size_t written = 0;
    for (;;) {
      if (pending_ == 0) pending_ = next_packet(packet_);
      if (pending_ == 0) return written;
      const std::size_t size = write_frame(framing_, out.subspan(written), counter_, packet_.first(pending_));
      if (size == 0) return written;  // it does not fit now: keep it for the next call
      ++counter_;
      written += size;
      pending_ = 0;
    }
  }

 private:
  Framing framing_;
  std::span<std::uint8_t> packet_;
  std::uint16_t counter_ = 0;
  std::size_t pending_ = 0;  // the size of a packet taken from the source that did not fit `out` yet
};

}  // namespace duet::xcp
