// The IPCC driver against a fake register file: the start-up sequence, masking and unmasking doorbells, which are
// pending, acknowledging, and ringing only a doorbell Linux has taken.
#include "duet/stm32mp15/ipcc.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace duet::stm32mp15 {
namespace {

class IpccTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return registers[offset / 4]; }
  std::array<std::uint32_t, 8> registers{};
  Ipcc ipcc{reinterpret_cast<std::uintptr_t>(registers.data())};
};

TEST_F(IpccTest, StartsWithEveryChannelMaskedAndCleared) {
  registers.fill(0xFFFF'FFFF);
  reg(Ipcc::c1toc2sr) = 0;
  reg(Ipcc::c2mr) = 0;  // a previous firmware's unmasked channels
  ipcc.start();
  EXPECT_EQ(reg(Ipcc::c2scr), 0x3FU);        // every channel's flag cleared
  EXPECT_EQ(reg(Ipcc::c2mr), 0x003F'003FU);  // every channel masked, receive and free
  EXPECT_EQ(reg(Ipcc::c2cr), Ipcc::receive_interrupt);
  EXPECT_EQ(reg(Ipcc::c1cr), 0xFFFF'FFFFU);  // Linux's registers untouched
}

TEST_F(IpccTest, MaskingAndUnmaskingChangeOnlyTheReceiveMasksAsked) {
  ipcc.start();
  ipcc.unmask_receive(1U << ipcc_channel::vring0 | 1U << ipcc_channel::vring1 | 1U << ipcc_channel::shutdown);
  EXPECT_EQ(reg(Ipcc::c2mr), 0x003F'0038U);  // free-channel interrupts still masked, channels 0-2 unmasked
  ipcc.mask_receive(1U << ipcc_channel::vring1);
  EXPECT_EQ(reg(Ipcc::c2mr), 0x003F'003AU);
  ipcc.unmask_receive(0xFFFF'FFFF);  // never a free-channel mask
  EXPECT_EQ(reg(Ipcc::c2mr), 0x003F'0000U);
}

TEST_F(IpccTest, PendingIsWhatLinuxRangAndIsUnmasked) {
  ipcc.start();
  ipcc.unmask_receive(1U << ipcc_channel::vring1 | 1U << ipcc_channel::shutdown);
  reg(Ipcc::c1toc2sr) = 1U << ipcc_channel::vring0 | 1U << ipcc_channel::vring1 | 1U << ipcc_channel::shutdown;
  EXPECT_EQ(ipcc.pending(), 1U << ipcc_channel::vring1 | 1U << ipcc_channel::shutdown);
  EXPECT_EQ(ipcc.rung(), 1U << ipcc_channel::vring0 | 1U << ipcc_channel::vring1 | 1U << ipcc_channel::shutdown);
  ipcc.acknowledge(ipcc_channel::shutdown);
  EXPECT_EQ(reg(Ipcc::c2scr), 1U << ipcc_channel::shutdown);  // CH3C: write one to clear
}

TEST_F(IpccTest, RingsOnlyADoorbellLinuxHasTaken) {
  ipcc.start();
  reg(Ipcc::c2scr) = 0;
  reg(Ipcc::c2toc1sr) = 1U << ipcc_channel::vring0;  // still set from the last ring
  EXPECT_FALSE(ipcc.ring(ipcc_channel::vring0));
  EXPECT_EQ(reg(Ipcc::c2scr), 0U);
  reg(Ipcc::c2toc1sr) = 0;
  EXPECT_TRUE(ipcc.ring(ipcc_channel::vring0));
  EXPECT_EQ(reg(Ipcc::c2scr), 1U << 16U);  // CH1S
}

}  // namespace
}  // namespace duet::stm32mp15
