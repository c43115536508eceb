#pragma once
// XCP over a byte stream for the slave: a UART, an RPMsg tty or a pty. Received bytes are decoded into commands for
// the Slave; its responses and DAQ packets leave through the transmit queue, so that they share one CTR sequence and
// one order. Freestanding: the firmware calls receive() from its receive interrupt and transmit() whenever the line
// can take bytes. The inter-processor channel uses XCP-on-TCP framing (LEN/CTR, docs/XCP.md).

#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/xcp/framing.hpp"
#include "duet/xcp/packet_framer.hpp"
#include "duet/xcp/slave.hpp"
#include "duet/xcp/transmit_queue.hpp"

namespace duet::xcp {

class StreamTransport {
 public:
  // `decoder_buffer` holds the largest command frame (framing.frame_size(max_cto)), `packet_buffer` the largest
  // outgoing packet (MAX_DTO, or MAX_CTO if larger); `queue` is the slave's. The application owns both buffers.
  StreamTransport(Slave& slave, TransmitQueue& queue, const Framing& framing, std::span<std::uint8_t> decoder_buffer,
                  std::size_t max_cto, std::span<std::uint8_t> packet_buffer)
      : slave_(slave), queue_(queue), decoder_(framing, decoder_buffer, max_cto), framer_(framing, packet_buffer) {}

  // Bytes from the line, in any pieces; each complete command is handled and its response queued (a response is
  // never refused: DAQ keeps room for it).
  void receive(std::span<const std::uint8_t> bytes);

  // Frames queued packets into `out` as far as whole frames fit; returns the bytes written (0: nothing to send).
  std::size_t transmit(std::span<std::uint8_t> out);

  [[nodiscard]] std::size_t dropped_bytes() const { return decoder_.dropped_bytes(); }

 private:
  Slave& slave_;
  TransmitQueue& queue_;
  FrameDecoder decoder_;
  PacketFramer framer_;
};

}  // namespace duet::xcp
