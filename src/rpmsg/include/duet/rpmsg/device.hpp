#pragma once
// RPMsg over two vrings, the device's end (the Cortex-M4), without OpenAMP. Linux's rpmsg_virtio driver offers
// empty buffers in vring0 (the M4 sends in them) and full ones in vring1 (the M4 receives them); every buffer starts
// with a 16-byte header {u32 src, u32 dst, u32 reserved, u16 len, u16 flags}, so a 512-byte buffer carries at most
// 496 bytes. An endpoint announces itself to Linux's name service (address 53) by name ("rpmsg-tty" makes a
// /dev/ttyRPMSGn); Linux never announces its end, so an endpoint learns where to send from the first message it
// receives. Freestanding and interrupt-driven: receive() from the doorbell's interrupt, send() from anywhere that
// holds the port's lock; neither waits.

#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/rpmsg/vring.hpp"

namespace duet::rpmsg {

inline constexpr std::size_t header_size = 16;
inline constexpr std::uint32_t name_service_address = 53;
inline constexpr std::size_t name_size = 32;
inline constexpr std::uint32_t first_local_address = 1024;

struct Endpoint {
  const char* name;     // the service Linux binds ("rpmsg-tty")
  std::uint32_t local;  // our address, from first_local_address on
  void (*received)(void* context, std::span<const std::uint8_t> payload);
  void* context;
  std::uint32_t remote = 0;  // Linux's address, learnt from its first message; 0 until then
};

enum class SendResult { sent, no_remote_yet, no_buffer, too_long };

struct DeviceConfiguration {
  DeviceVring* transmit;  // vring0
  DeviceVring* receive;   // vring1
  // Linux's buffer address as the M4 sees it (the same on the STM32MP15's MCU SRAM; an offset in the PC's tests).
  std::uint8_t* (*buffer_at)(std::uint64_t address);
  // Rings the doorbell of `vring` (0 or 1) to tell Linux it has used buffers.
  void (*notify)(unsigned vring);
  std::span<Endpoint> endpoints;
};

class Device {
 public:
  explicit Device(const DeviceConfiguration& configuration) : configuration_(configuration) {}

  // Tells Linux's name service of every endpoint; false if a buffer was missing (call again later).
  bool announce();
  // Sends `payload` from `endpoint` to Linux; never waits.
  SendResult send(Endpoint& endpoint, std::span<const std::uint8_t> payload);
  // Takes every buffer Linux sent, hands each payload to its endpoint, gives the buffers back.
  void receive();

  [[nodiscard]] std::uint32_t dropped_messages() const { return dropped_; }

 private:
  bool send_from(std::uint32_t source, std::uint32_t destination, std::span<const std::uint8_t> first,
                 std::span<const std::uint8_t> second = {});

  DeviceConfiguration configuration_;
  std::size_t announced_ = 0;
  std::uint32_t dropped_ = 0;  // for no endpoint, or malformed
};

}  // namespace duet::rpmsg
