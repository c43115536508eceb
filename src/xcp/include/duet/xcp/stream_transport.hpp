#pragma once
// XCP over a byte stream for the slave: a UART, an RPMsg tty or a pty. Received bytes are decoded into commands for
// the Slave; its responses and DAQ packets leave through the transmit queue, so that they share one CTR sequence and
// one order. Freestanding: the firmware calls receive() from its receive interrupt and transmit() whenever the line
// can take bytes. The inter-processor channel uses XCP-on-TCP framing (LEN/CTR, docs/XCP.md).

#include <atomic>
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

  // Bytes from the line, in any pieces; each complete command is handled and its response queued. DAQ keeps room for
  // one response, so only a master that sends commands without reading the answers fills the queue: a response that
  // does not fit is dropped and counted (responses_dropped), and the master sees its command time out.
  void receive(std::span<const std::uint8_t> bytes);

  // Frames queued packets into `out` as far as whole frames fit; returns the bytes written (0: nothing to send).
  std::size_t transmit(std::span<std::uint8_t> out);

  [[nodiscard]] std::size_t dropped_bytes() const { return decoder_.dropped_bytes(); }
  [[nodiscard]] std::uint32_t responses_dropped() const { return responses_dropped_.load(std::memory_order_relaxed); }

 private:
  Slave& slave_;
  TransmitQueue& queue_;
  FrameDecoder decoder_;
  PacketFramer framer_;
  std::atomic<std::uint32_t> responses_dropped_{0};  // read from another context than the one that counts
};

}  // namespace duet::xcp
