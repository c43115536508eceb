#pragma once
// For tests: Linux's end of RPMsg as rpmsg_virtio keeps it, in shared memory: vring0 to receive (it offers empty
// buffers), vring1 to transmit (it offers full ones and takes them back when the device has read them), and 32
// buffers of 512 bytes. Addresses are offsets into the test's shared memory (buffer_at translates them).

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "driver_vring.hpp"
#include "duet/rpmsg/device.hpp"

namespace duet::rpmsg::testing {

constexpr VringLayout layout{16, 16};
constexpr std::uint64_t vring1_at = 0x1000;
constexpr std::uint64_t buffers_at = 0x2000;
constexpr std::uint32_t buffer_size = 512;

inline std::uint8_t* shared_memory = nullptr;  // what Device's buffer_at translates into, per test
inline std::uint8_t* buffer_at(std::uint64_t address) { return shared_memory + address; }

class LinuxSide {
 public:
  struct Message {
    std::uint32_t source;
    std::uint32_t destination;
    std::vector<std::uint8_t> payload;
  };

  LinuxSide() {
    shared_memory = memory_.data();
    for (std::uint32_t buffer = 0; buffer < 16; ++buffer)
      receiving_.offer(buffers_at + buffer_size * buffer, buffer_size);
    for (std::uint32_t buffer = 16; buffer < 32; ++buffer) free_.push_back(buffers_at + buffer_size * buffer);
  }

  std::uint8_t* memory() { return memory_.data(); }

  // False when every transmit buffer is with the device (the tty's write fails with ENOMEM).
  bool send(std::uint32_t source, std::uint32_t destination, const std::vector<std::uint8_t>& payload) {
    while (const auto used = transmitting_.collect()) free_.push_back(used->address);
    if (free_.empty()) return false;
    const std::uint64_t address = free_.back();
    free_.pop_back();
    std::uint8_t* bytes = memory_.data() + address;
    const auto length = static_cast<std::uint16_t>(payload.size());
    std::memcpy(bytes, &source, 4);
    std::memcpy(bytes + 4, &destination, 4);
    std::memset(bytes + 8, 0, 4);
    std::memcpy(bytes + 12, &length, 2);
    std::memset(bytes + 14, 0, 2);
    std::memcpy(bytes + header_size, payload.data(), payload.size());
    return transmitting_.offer(address, buffer_size);
  }

  // Every message the device sent since, buffers offered again.
  std::vector<Message> receive() {
    std::vector<Message> messages;
    while (const auto used = receiving_.collect()) {
      const std::uint8_t* bytes = memory_.data() + used->address;
      Message message{};
      std::uint16_t length = 0;
      std::memcpy(&message.source, bytes, 4);
      std::memcpy(&message.destination, bytes + 4, 4);
      std::memcpy(&length, bytes + 12, 2);
      EXPECT_EQ(used->length, header_size + length);
      message.payload.assign(bytes + header_size, bytes + header_size + length);
      messages.push_back(std::move(message));
      receiving_.offer(used->address, buffer_size);
    }
    return messages;
  }

 private:
  std::vector<std::uint8_t> memory_ = std::vector<std::uint8_t>(buffers_at + 32 * buffer_size);
  DriverVring receiving_{memory_.data(), layout};
  DriverVring transmitting_{memory_.data() + vring1_at, layout};
  std::vector<std::uint64_t> free_;
};

}  // namespace duet::rpmsg::testing
