#pragma once
// A byte stream over one RPMsg endpoint: the device's end of a Linux rpmsg-tty (/dev/ttyRPMSGn). What Linux writes
// reaches a byte protocol (XCP's StreamTransport, the application channel's Endpoint) as it arrives, in whatever
// pieces; what the protocol has queued leaves in messages of at most 496 bytes, as far as Linux has buffers. A tty
// keeps no message boundaries, so the protocol's own framing carries them. The protocol needs
// receive(std::span<const std::uint8_t>) and transmit(std::span<std::uint8_t>) returning the bytes it framed into the
// span (0: nothing queued), as on a UART (ports/mps2-an386/include/duet/mps2_an386/uart_line.hpp).
//
// Not reentrant: the device's receive() and every pump() run from one interrupt handler (the doorbell's).

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/rpmsg/device.hpp"

namespace duet::rpmsg {

inline constexpr std::size_t max_payload = 512 - header_size;

class ByteChannel {
 public:
  template <typename Protocol>
  explicit ByteChannel(Protocol& protocol)
      : protocol_(&protocol),
        receive_([](void* context, std::span<const std::uint8_t> bytes) {
          static_cast<Protocol*>(context)->receive(bytes);
        }),
        transmit_([](void* context, std::span<std::uint8_t> out) -> std::size_t {
          return static_cast<Protocol*>(context)->transmit(out);
        }) {}

  // The endpoint Device serves for this channel: announced as `name` ("rpmsg-tty") at address `local`.
  [[nodiscard]] Endpoint endpoint(const char* name, std::uint32_t local) {
    return Endpoint{name, local, &ByteChannel::received, this};
  }

  // Sends what the protocol has queued, one message per call of its transmit(), until it has nothing more or Linux
  // has no free buffer; a message that found none waits here for the next pump (Linux rings when it returns
  // buffers). Until Linux has written to the tty nobody reads it, and there is nowhere to send: what is queued then
  // is dropped and counted, so that a reader's first bytes are fresh.
  void pump(Device& device, Endpoint& endpoint);

  [[nodiscard]] std::uint32_t bytes_received() const { return bytes_received_; }
  [[nodiscard]] std::uint32_t bytes_sent() const { return bytes_sent_; }
  [[nodiscard]] std::uint32_t bytes_dropped_without_reader() const { return bytes_dropped_; }
  // Times a message waited because Linux had no free buffer.
  [[nodiscard]] std::uint32_t waits_for_buffers() const { return waits_; }

 private:
  static void received(void* context, std::span<const std::uint8_t> payload);

  void* protocol_;
  void (*receive_)(void*, std::span<const std::uint8_t>);
  std::size_t (*transmit_)(void*, std::span<std::uint8_t>);
  std::array<std::uint8_t, max_payload> message_{};
  std::size_t held_ = 0;  // bytes of message_ framed and not sent yet
  std::uint32_t bytes_received_ = 0;
  std::uint32_t bytes_sent_ = 0;
  std::uint32_t bytes_dropped_ = 0;
  std::uint32_t waits_ = 0;
};

}  // namespace duet::rpmsg
