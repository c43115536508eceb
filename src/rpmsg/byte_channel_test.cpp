// A byte protocol over an RPMsg endpoint, against a Linux side that behaves as rpmsg_virtio and the tty driver do:
// bytes both ways arrive whole and in order whatever the message sizes, a message waits while Linux has no buffer,
// and bytes queued before anyone reads the tty are dropped and counted.
#include "duet/rpmsg/byte_channel.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "linux_side.hpp"
#include "recording_protocol.hpp"

namespace duet::rpmsg {
namespace {

using testing::buffer_at;
using testing::layout;
using testing::LinuxSide;
using testing::vring1_at;

using testing::RecordingProtocol;

void no_doorbell(unsigned) {}

class ByteChannelTest : public ::testing::Test {
 protected:
  std::vector<std::uint8_t> linux_reads() {
    std::vector<std::uint8_t> bytes;
    for (const auto& message : linux_side.receive()) {
      EXPECT_LE(message.payload.size(), max_payload);
      bytes.insert(bytes.end(), message.payload.begin(), message.payload.end());
    }
    return bytes;
  }

  LinuxSide linux_side;
  DeviceVring transmit{linux_side.memory(), layout};
  DeviceVring receive{linux_side.memory() + vring1_at, layout};
  RecordingProtocol protocol;
  ByteChannel channel{protocol};
  std::array<Endpoint, 1> endpoints{channel.endpoint("rpmsg-tty", first_local_address)};
  Device device{{&transmit, &receive, buffer_at, no_doorbell, endpoints}};
};

TEST_F(ByteChannelTest, WhatIsQueuedBeforeLinuxWritesIsDroppedAndCounted) {
  protocol.queued.assign(250, 0xAB);
  channel.pump(device, endpoints[0]);
  EXPECT_TRUE(protocol.queued.empty());
  EXPECT_EQ(channel.bytes_dropped_without_reader(), 250U);
  EXPECT_EQ(channel.bytes_sent(), 0U);
  ASSERT_TRUE(device.announce());
  EXPECT_EQ(linux_side.receive().size(), 1U);  // the announcement only
}

TEST_F(ByteChannelTest, BytesFromLinuxReachTheProtocolInOrder) {
  ASSERT_TRUE(linux_side.send(2000, first_local_address, {1, 2, 3}));
  ASSERT_TRUE(linux_side.send(2000, first_local_address, {4}));
  device.receive();
  EXPECT_EQ(protocol.received, (std::vector<std::uint8_t>{1, 2, 3, 4}));
  EXPECT_EQ(channel.bytes_received(), 4U);
  EXPECT_EQ(endpoints[0].remote, 2000U);
}

TEST_F(ByteChannelTest, AMessageWaitsForABufferAndNothingIsLost) {
  ASSERT_TRUE(linux_side.send(2000, first_local_address, {0}));
  device.receive();
  // 40 KB queued: 16 buffers of 496 bytes take 7,936 (frames of 100 fill 400 of each).
  std::vector<std::uint8_t> stream(40'000);
  for (std::size_t at = 0; at < stream.size(); ++at) stream[at] = static_cast<std::uint8_t>(at * 7 + at / 256);
  protocol.queued.assign(stream.begin(), stream.end());
  std::vector<std::uint8_t> arrived;
  for (int round = 0; round < 100 && arrived.size() < stream.size(); ++round) {
    channel.pump(device, endpoints[0]);
    const auto bytes = linux_reads();
    arrived.insert(arrived.end(), bytes.begin(), bytes.end());
  }
  EXPECT_EQ(arrived, stream);
  EXPECT_GT(channel.waits_for_buffers(), 0U);
  EXPECT_EQ(channel.bytes_sent(), stream.size());
  EXPECT_EQ(channel.bytes_dropped_without_reader(), 0U);
}

TEST_F(ByteChannelTest, RandomTrafficBothWaysArrivesWholeAndInOrder) {
  std::mt19937 random{11};
  std::uniform_int_distribution<std::size_t> size_of{1, 496};
  std::uniform_int_distribution<int> byte_of{0, 255};
  std::vector<std::uint8_t> linux_sent, device_queued, linux_received;
  for (int turn = 0; turn < 5'000; ++turn) {
    std::vector<std::uint8_t> message(size_of(random));
    for (auto& byte : message) byte = static_cast<std::uint8_t>(byte_of(random));
    if (turn % 2 == 0) {
      if (linux_side.send(2000, first_local_address, message)) {
        linux_sent.insert(linux_sent.end(), message.begin(), message.end());
      }
      device.receive();
    } else {
      protocol.frame_size = message.size();
      protocol.queued.insert(protocol.queued.end(), message.begin(), message.end());
      device_queued.insert(device_queued.end(), message.begin(), message.end());
      channel.pump(device, endpoints[0]);
      if (turn % 3 == 0) {
        const auto bytes = linux_reads();
        linux_received.insert(linux_received.end(), bytes.begin(), bytes.end());
      }
    }
  }
  for (int round = 0; round < 100 && !protocol.queued.empty(); ++round) {
    channel.pump(device, endpoints[0]);
    const auto bytes = linux_reads();
    linux_received.insert(linux_received.end(), bytes.begin(), bytes.end());
  }
  channel.pump(device, endpoints[0]);
  const auto rest = linux_reads();
  linux_received.insert(linux_received.end(), rest.begin(), rest.end());
  EXPECT_EQ(protocol.received, linux_sent);
  EXPECT_EQ(linux_received, device_queued);
}

}  // namespace
}  // namespace duet::rpmsg
