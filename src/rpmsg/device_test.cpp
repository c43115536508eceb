// RPMsg between the device (as the M4 runs it) and a Linux side that behaves as rpmsg_virtio does, through two
// vrings and 32 buffers of 512 bytes in shared memory: the name service, two channels, buffers running out, and
// 10,000 messages each way of random sizes, none lost or reordered.
#include "duet/rpmsg/device.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "linux_side.hpp"

namespace duet::rpmsg {
namespace {

using testing::buffer_at;
using testing::layout;
using testing::LinuxSide;
using testing::vring1_at;

struct Inbox {
  std::vector<std::vector<std::uint8_t>> messages;
  static void take(void* context, std::span<const std::uint8_t> payload) {
    static_cast<Inbox*>(context)->messages.emplace_back(payload.begin(), payload.end());
  }
};

std::array<unsigned, 2> doorbells{};
void ring(unsigned vring) { ++doorbells.at(vring); }

class DeviceTest : public ::testing::Test {
 protected:
  LinuxSide linux_side;
  DeviceVring transmit{linux_side.memory(), layout};
  DeviceVring receive{linux_side.memory() + vring1_at, layout};
  std::array<Inbox, 2> inboxes;
  std::array<Endpoint, 2> endpoints{Endpoint{"rpmsg-tty", first_local_address, Inbox::take, &inboxes[0]},
                                    Endpoint{"rpmsg-tty", first_local_address + 1, Inbox::take, &inboxes[1]}};
  Device device{{&transmit, &receive, buffer_at, ring, endpoints}};
};

TEST_F(DeviceTest, EachChannelIsAnnouncedToTheNameService) {
  doorbells = {};
  ASSERT_TRUE(device.announce());
  const auto messages = linux_side.receive();
  ASSERT_EQ(messages.size(), 2U);
  for (std::size_t channel = 0; channel < 2; ++channel) {
    const auto& message = messages[channel];
    EXPECT_EQ(message.destination, name_service_address);
    EXPECT_EQ(message.source, first_local_address + channel);
    ASSERT_EQ(message.payload.size(), name_size + 8);
    EXPECT_EQ(std::string(reinterpret_cast<const char*>(message.payload.data())), "rpmsg-tty");
    std::uint32_t address = 0;
    std::memcpy(&address, message.payload.data() + name_size, 4);
    EXPECT_EQ(address, first_local_address + channel);
  }
  EXPECT_EQ(doorbells[0], 2U);
}

TEST_F(DeviceTest, AnEndpointSendsOnlyOnceLinuxHasWritten) {
  const std::vector<std::uint8_t> hello{'h', 'i'};
  EXPECT_EQ(device.send(endpoints[0], hello), SendResult::no_remote_yet);
  ASSERT_TRUE(linux_side.send(0x400 + 77, first_local_address, hello));
  device.receive();
  ASSERT_EQ(inboxes[0].messages.size(), 1U);
  EXPECT_EQ(inboxes[0].messages[0], hello);
  EXPECT_EQ(endpoints[0].remote, 0x400U + 77);
  EXPECT_EQ(device.send(endpoints[0], hello), SendResult::sent);
  const auto answers = linux_side.receive();
  ASSERT_EQ(answers.size(), 1U);
  EXPECT_EQ(answers[0].destination, 0x400U + 77);
  EXPECT_EQ(device.send(endpoints[0], std::vector<std::uint8_t>(497)), SendResult::too_long);
}

TEST_F(DeviceTest, BuffersRunOutAndComeBack) {
  // Linux writes 16 messages that the device has not read: the 17th finds no buffer.
  const std::vector<std::uint8_t> payload(496, 0x5A);
  for (int message = 0; message < 16; ++message) ASSERT_TRUE(linux_side.send(2000, first_local_address, payload));
  EXPECT_FALSE(linux_side.send(2000, first_local_address, payload));
  device.receive();
  EXPECT_EQ(inboxes[0].messages.size(), 16U);
  EXPECT_TRUE(linux_side.send(2000, first_local_address, payload));
  device.receive();
  // The device sends 16 that Linux has not read: the 17th finds no buffer, and none is lost.
  for (int message = 0; message < 16; ++message) ASSERT_EQ(device.send(endpoints[0], payload), SendResult::sent);
  EXPECT_EQ(device.send(endpoints[0], payload), SendResult::no_buffer);
  EXPECT_EQ(linux_side.receive().size(), 16U);
  EXPECT_EQ(device.send(endpoints[0], payload), SendResult::sent);
  EXPECT_EQ(linux_side.receive().size(), 1U);
}

TEST_F(DeviceTest, AMessageForNoEndpointIsDroppedAndCounted) {
  ASSERT_TRUE(linux_side.send(2000, 999, {1, 2, 3}));
  device.receive();
  EXPECT_EQ(device.dropped_messages(), 1U);
  EXPECT_TRUE(inboxes[0].messages.empty());
}

// A message's bytes: its sequence number, then bytes that follow from it, so a mix-up shows.
std::vector<std::uint8_t> message_bytes(std::uint32_t sequence, std::size_t size) {
  std::vector<std::uint8_t> bytes(size);
  for (std::size_t at = 0; at < size; ++at) bytes[at] = static_cast<std::uint8_t>(sequence * 31U + at);
  if (size >= 4) std::memcpy(bytes.data(), &sequence, 4);
  return bytes;
}

TEST_F(DeviceTest, TenThousandMessagesEachWayArriveWholeAndInOrder) {
  constexpr std::uint32_t count = 10'000;
  std::mt19937 random{2026};
  std::uniform_int_distribution<std::size_t> size_of{4, 496};
  std::array<std::uint32_t, 2> linux_sent{}, device_sent{}, linux_received{};
  std::vector<std::size_t> linux_sizes[2], device_sizes[2];
  // Linux writes first on each channel, so that the device learns where to answer.
  for (std::uint32_t channel = 0; channel < 2; ++channel) {
    const std::size_t size = size_of(random);
    ASSERT_TRUE(linux_side.send(3000 + channel, first_local_address + channel, message_bytes(0, size)));
    linux_sizes[channel].push_back(size);
    linux_sent[channel] = 1;
  }
  device.receive();
  const auto check_linux_inbox = [&] {
    for (const auto& message : linux_side.receive()) {
      const std::uint32_t channel = message.source - first_local_address;
      ASSERT_LT(channel, 2U);
      ASSERT_EQ(message.destination, 3000 + channel);
      const std::uint32_t sequence = linux_received[channel]++;
      ASSERT_EQ(message.payload, message_bytes(sequence, device_sizes[channel][sequence]));
    }
  };
  std::bernoulli_distribution linux_turn{0.5};
  std::uniform_int_distribution<std::uint32_t> channel_of{0, 1};
  while (linux_sent[0] + linux_sent[1] < 2 * count || device_sent[0] + device_sent[1] < 2 * count) {
    const std::uint32_t channel = channel_of(random);
    if (linux_turn(random)) {
      if (linux_sent[channel] == count) continue;
      const std::size_t size = size_of(random);
      if (linux_side.send(3000 + channel, first_local_address + channel, message_bytes(linux_sent[channel], size))) {
        linux_sizes[channel].push_back(size);
        ++linux_sent[channel];
      } else {
        device.receive();  // out of buffers: the device's interrupt comes
      }
    } else {
      if (device_sent[channel] == count) continue;
      const std::size_t size = size_of(random);
      const auto result = device.send(endpoints[channel], message_bytes(device_sent[channel], size));
      if (result == SendResult::sent) {
        device_sizes[channel].push_back(size);
        ++device_sent[channel];
      } else {
        ASSERT_EQ(result, SendResult::no_buffer);
        check_linux_inbox();  // Linux reads
      }
    }
  }
  device.receive();
  check_linux_inbox();
  for (std::uint32_t channel = 0; channel < 2; ++channel) {
    EXPECT_EQ(linux_received[channel], count);
    ASSERT_EQ(inboxes[channel].messages.size(), count);
    for (std::uint32_t sequence = 0; sequence < count; ++sequence) {
      ASSERT_EQ(inboxes[channel].messages[sequence], message_bytes(sequence, linux_sizes[channel][sequence]))
          << "channel " << channel << ", message " << sequence;
    }
  }
  EXPECT_EQ(device.dropped_messages(), 0U);
}

}  // namespace
}  // namespace duet::rpmsg
