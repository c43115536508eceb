// The device's side of a vring against a driver that behaves as Linux's: buffers offered, taken, handed back, in
// order, across the 16-bit wrap of the indices; an empty ring; a driver that asks for quiet; a bad descriptor.
#include "duet/rpmsg/vring.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "driver_vring.hpp"

namespace duet::rpmsg {
namespace {

constexpr VringLayout layout{16, 16};

class VringTest : public ::testing::Test {
 protected:
  std::vector<std::uint8_t> memory = std::vector<std::uint8_t>(layout.size());
  testing::DriverVring driver{memory.data(), layout};
};

TEST_F(VringTest, BuffersComeBackInOrderWithTheLengthWritten) {
  DeviceVring device{memory.data(), layout};
  EXPECT_FALSE(device.take());  // nothing offered yet
  for (std::uint64_t buffer = 0; buffer < 16; ++buffer) ASSERT_TRUE(driver.offer(0x1000 + 512 * buffer, 512));
  EXPECT_FALSE(driver.offer(0x9000, 512));  // every descriptor is out
  EXPECT_EQ(device.offered(), 16);
  for (std::uint32_t buffer = 0; buffer < 16; ++buffer) {
    const auto taken = device.take();
    ASSERT_TRUE(taken);
    EXPECT_EQ(taken->address, 0x1000 + 512U * buffer);
    EXPECT_EQ(taken->length, 512U);
    device.give_back(taken->head, buffer + 1);
  }
  EXPECT_FALSE(device.take());
  for (std::uint32_t buffer = 0; buffer < 16; ++buffer) {
    const auto used = driver.collect();
    ASSERT_TRUE(used);
    EXPECT_EQ(used->address, 0x1000 + 512U * buffer);
    EXPECT_EQ(used->length, buffer + 1);
  }
  EXPECT_FALSE(driver.collect());
}

TEST_F(VringTest, TheIndicesWrapAt16Bits) {
  driver.start_indices_at(65'530);
  DeviceVring device{memory.data(), layout};  // picks up the indices where they stand
  std::uint64_t next_address = 0;
  std::uint64_t expected = 0;
  // The device keeps up to 5 buffers and the driver refills whatever comes back: 70 laps of the ring.
  for (int round = 0; round < 70 * 16; ++round) {
    while (driver.offer(next_address, 100)) ++next_address;
    const auto taken = device.take();
    ASSERT_TRUE(taken);
    EXPECT_EQ(taken->address, expected++);
    device.give_back(taken->head, 7);
    const auto used = driver.collect();
    ASSERT_TRUE(used);
    EXPECT_EQ(used->length, 7U);
  }
}

TEST_F(VringTest, TheDeviceLearnsTheDriverWantsQuiet) {
  DeviceVring device{memory.data(), layout};
  EXPECT_TRUE(device.driver_wants_interrupt());
  driver.set_no_interrupt(true);
  EXPECT_FALSE(device.driver_wants_interrupt());
}

TEST_F(VringTest, AChainedDescriptorIsHandedBackUnread) {
  DeviceVring device{memory.data(), layout};
  ASSERT_TRUE(driver.offer(0x2000, 512, descriptor_next));
  const auto taken = device.take();
  ASSERT_TRUE(taken);
  EXPECT_EQ(taken->address, 0U);
  EXPECT_EQ(taken->length, 0U);
  device.give_back(taken->head, 0);
  const auto used = driver.collect();
  ASSERT_TRUE(used);
  EXPECT_EQ(used->address, 0x2000U);
}

}  // namespace
}  // namespace duet::rpmsg
