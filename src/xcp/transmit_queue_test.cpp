#include "duet/xcp/transmit_queue.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace duet::xcp {
namespace {

std::mutex queue_mutex;
std::uint32_t lock_mutex() {
  queue_mutex.lock();
  return 0;
}
void unlock_mutex(std::uint32_t) { queue_mutex.unlock(); }
constexpr QueueLock mutex_lock{lock_mutex, unlock_mutex};

bool push_packet(TransmitQueue& queue, std::span<const std::uint8_t> packet, std::size_t headroom = 0) {
  return queue.push(packet.size() + TransmitQueue::record_header, headroom,
                    [&](auto& out) { out.packet(packet.size()).bytes(packet.data(), packet.size()); });
}

TEST(TransmitQueue, KeepsPacketsInOrderAcrossTheRingsEnd) {
  std::array<std::uint8_t, 16> storage{};
  TransmitQueue queue{storage, {}};
  std::array<std::uint8_t, 16> out{};
  for (std::uint8_t round = 0; round < 10; ++round) {  // 5-byte records wrap round a 16-byte ring
    const std::array<std::uint8_t, 3> packet{round, static_cast<std::uint8_t>(round + 1), 0xEE};
    ASSERT_TRUE(push_packet(queue, packet));
    ASSERT_EQ(queue.pop(out), 3U);
    EXPECT_EQ(out[0], round);
    EXPECT_EQ(out[1], round + 1);
    EXPECT_EQ(out[2], 0xEE);
  }
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(queue.pop(out), 0U);
}

TEST(TransmitQueue, RefusesWhatDoesNotFitWholeAndKeepsHeadroom) {
  std::array<std::uint8_t, 16> storage{};
  TransmitQueue queue{storage, {}};
  const std::array<std::uint8_t, 6> packet{1, 2, 3, 4, 5, 6};
  EXPECT_TRUE(push_packet(queue, packet));      // 8 of 16 bytes
  EXPECT_FALSE(push_packet(queue, packet, 1));  // 8 more fit, but not with one byte to spare
  EXPECT_TRUE(push_packet(queue, packet));      // full
  EXPECT_FALSE(push_packet(queue, std::array<std::uint8_t, 1>{9}));
  std::array<std::uint8_t, 8> out{};
  EXPECT_EQ(queue.pop(out), 6U);
  EXPECT_EQ(queue.pop(out), 6U);
  EXPECT_TRUE(queue.empty());
}

// Two producers and a consumer on three threads: every packet arrives whole and each producer's in its order.
TEST(TransmitQueue, ConcurrentProducersNeverInterleaveTheirPackets) {
  std::array<std::uint8_t, 256> storage{};
  TransmitQueue queue{storage, mutex_lock};
  constexpr std::uint32_t packets_each = 20'000;
  auto produce = [&](std::uint8_t producer) {
    for (std::uint32_t number = 0; number < packets_each;) {
      std::array<std::uint8_t, 9> packet{producer};
      for (std::size_t byte = 1; byte < packet.size(); byte += 4) {
        for (std::size_t shift = 0; shift < 4; ++shift)
          packet[byte + shift] = static_cast<std::uint8_t>(number >> (8 * shift));
      }
      if (push_packet(queue, packet)) ++number;
    }
  };
  std::thread first{produce, std::uint8_t{1}};
  std::thread second{produce, std::uint8_t{2}};
  std::array<std::uint32_t, 3> next{0, 0, 0};
  std::uint32_t damaged = 0;
  std::array<std::uint8_t, 16> out{};
  while (next[1] < packets_each || next[2] < packets_each) {
    const std::size_t size = queue.pop(out);
    if (size == 0) continue;
    const std::uint8_t producer = out[0];
    const std::uint32_t number = static_cast<std::uint32_t>(out[1]) | (static_cast<std::uint32_t>(out[2]) << 8U) |
                                 (static_cast<std::uint32_t>(out[3]) << 16U) |
                                 (static_cast<std::uint32_t>(out[4]) << 24U);
    const bool whole = size == 9 && (producer == 1 || producer == 2) && out[5] == out[1] && out[8] == out[4];
    if (!whole || number != next[producer]) {
      ++damaged;
      break;
    }
    ++next[producer];
  }
  first.join();
  second.join();
  EXPECT_EQ(damaged, 0U);
  EXPECT_EQ(next[1], packets_each);
  EXPECT_EQ(next[2], packets_each);
}

}  // namespace
}  // namespace duet::xcp
