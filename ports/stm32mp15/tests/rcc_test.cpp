// Peripheral clocks against a fake register file: one store of one bit to the right MC_xxxENSETR register each, so
// that no other bit (another core's) is written; SPI4/5's kernel clock from each source the boot loader may select.
#include "duet/stm32mp15/rcc.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace duet::stm32mp15 {
namespace {

class RccTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return registers[offset / 4]; }
  std::vector<std::uint32_t> registers = std::vector<std::uint32_t>(0xAB0 / 4);
  static constexpr std::uint32_t mcu_hz = 209'000'000, hse_hz = 24'000'000;
  Rcc rcc{reinterpret_cast<std::uintptr_t>(registers.data())};
};

TEST_F(RccTest, EachClockIsOneBitInItsSetRegister) {
  rcc.enable(clock::tim7);
  EXPECT_EQ(reg(0xA80), 1U << 5);
  rcc.enable(clock::tim2);
  EXPECT_EQ(reg(0xA80), 1U << 0);  // a store, not a read-modify-write: the set register keeps the others
  rcc.enable(clock::spi5);
  EXPECT_EQ(reg(0xA88), 1U << 10);
  rcc.enable(clock::dmamux);
  EXPECT_EQ(reg(0xA98), 1U << 2);
  rcc.enable(clock::ipcc);
  EXPECT_EQ(reg(0xAA0), 1U << 12);
  rcc.enable(clock::hsem);
  EXPECT_EQ(reg(0xAA0), 1U << 11);
  rcc.enable(clock::gpio(7));  // GPIOH
  EXPECT_EQ(reg(0xAA8), 1U << 7);
}

TEST_F(RccTest, Spi45KernelClockFromPclk2IsTheMcuClockOverApb2Div) {
  reg(Rcc::spi45ckselr) = 0;  // reset value: pclk2
  reg(Rcc::apb2divr) = 1;     // the DK2's: /2
  KernelClock clock = rcc.spi45_kernel_clock(mcu_hz, hse_hz);
  EXPECT_EQ(clock.source, Spi45ClockSource::pclk2);
  EXPECT_EQ(clock.hz, 104'500'000U);
  reg(Rcc::apb2divr) = 0;
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).hz, 209'000'000U);
  reg(Rcc::apb2divr) = 6;  // 4 and above: /16
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).hz, 13'062'500U);
  reg(Rcc::apb2divr) = 0xFFFF'FFF3;  // other bits ignored: /8
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).hz, 26'125'000U);
}

TEST_F(RccTest, Spi45KernelClockFromHsiIs64MhzOverHsidiv) {
  reg(Rcc::spi45ckselr) = 2;
  reg(Rcc::hsicfgr) = 0;
  KernelClock clock = rcc.spi45_kernel_clock(mcu_hz, hse_hz);
  EXPECT_EQ(clock.source, Spi45ClockSource::hsi);
  EXPECT_EQ(clock.hz, 64'000'000U);
  reg(Rcc::hsicfgr) = 0x0040'0003;  // HSIDIV /8, a calibration value above it
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).hz, 8'000'000U);
}

TEST_F(RccTest, Spi45KernelClockFromCsiOrHse) {
  reg(Rcc::spi45ckselr) = 3;
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).source, Spi45ClockSource::csi);
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).hz, 4'000'000U);
  reg(Rcc::spi45ckselr) = 4;
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).source, Spi45ClockSource::hse);
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).hz, 24'000'000U);
}

TEST_F(RccTest, Spi45KernelClockDuetCannotTellHasNoRate) {
  reg(Rcc::spi45ckselr) = 1;  // PLL4's Q output: its settings are not read
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).source, Spi45ClockSource::pll4_q);
  EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).hz, 0U);
  EXPECT_EQ(name(Spi45ClockSource::pll4_q), "pll4_q");
  for (const std::uint32_t off : {5U, 6U, 7U}) {
    reg(Rcc::spi45ckselr) = off;
    EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).source, Spi45ClockSource::off);
    EXPECT_EQ(rcc.spi45_kernel_clock(mcu_hz, hse_hz).hz, 0U);
  }
  EXPECT_EQ(name(Spi45ClockSource::off), "off");
}

}  // namespace
}  // namespace duet::stm32mp15
