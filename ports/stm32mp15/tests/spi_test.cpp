// SPI5 as the MPU6500's master against fake register files (SPI5, DMA2, DMAMUX1): the baud divider, the start-up
// configuration, a 15-byte sensor read in RM0436's DMA order, its end on the receive stream's completion, refusals
// while a transfer runs, and the errors counted. The test plays the DMA's part by writing the receive buffer.
#include "duet/stm32mp15/spi.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace duet::stm32mp15 {
namespace {

using Spi = SpiMaster<32>;

constexpr std::uint32_t lisr = 0x00, lifcr = 0x08;
constexpr std::uint32_t stream_cr = 0x10, ndtr = 0x14, par = 0x18, m0ar = 0x1C;
constexpr unsigned receive_stream = 2, transmit_stream = 3;
constexpr std::uint32_t receive_complete = 1U << 21, receive_error = 1U << 19;    // TCIF2, TEIF2
constexpr std::uint32_t transmit_complete = 1U << 27, transmit_error = 1U << 25;  // TCIF3, TEIF3

// The MPU6500's sensor read: ACCEL_XOUT_H (0x3B) with the read bit, then 14 dummy bytes.
constexpr std::array<std::uint8_t, 15> sensor_read{0xBB};

class SpiTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return spi_registers[offset / 4]; }
  std::uint32_t& stream_reg(unsigned index, std::uint32_t offset) { return dma[(offset + 0x18 * index) / 4]; }
  DmaStream stream(unsigned n) {
    return DmaStream{reinterpret_cast<std::uintptr_t>(dma.data()), n, reinterpret_cast<std::uintptr_t>(&dmamux[8 + n])};
  }
  std::uintptr_t spi_base() { return reinterpret_cast<std::uintptr_t>(spi_registers.data()); }
  // Memory at a DMA address: the M4's 32-bit addresses are the low half of the PC's.
  std::uint8_t* memory_at(std::uint32_t address) {
    return reinterpret_cast<std::uint8_t*>((reinterpret_cast<std::uintptr_t>(&spi) & ~std::uintptr_t{0xFFFF'FFFF}) |
                                           address);
  }
  // What the streams do when all frames are through: the received bytes in memory, EN cleared, flags set.
  void finish_transfer(std::span<const std::uint8_t> received) {
    std::uint8_t* buffer = memory_at(stream_reg(receive_stream, m0ar));
    for (std::size_t i = 0; i < received.size(); ++i) buffer[i] = received[i];
    stream_reg(receive_stream, stream_cr) &= ~1U;
    stream_reg(transmit_stream, stream_cr) &= ~1U;
    dma[lisr / 4] = receive_complete | transmit_complete;
    reg(Spi::sr) = Spi::end_of_transfer | Spi::transfer_filled;
  }
  void start_at_pclk2() {
    reg(Spi::cfg1) = 0x0007'0007;  // reset value
    ASSERT_TRUE(spi.start(104'500'000, 1'000'000));
  }

  std::array<std::uint32_t, 16> spi_registers{};
  std::array<std::uint32_t, 0xD0 / 4> dma{};
  std::array<std::uint32_t, 16> dmamux{};
  Spi spi{spi_base(), stream(transmit_stream), dma_request::spi5_tx, stream(receive_stream), dma_request::spi5_rx};
};

TEST_F(SpiTest, BaudRateIsTheFastestAtMostTheLimit) {
  EXPECT_EQ(Spi::baud_rate_setting(104'500'000, 1'000'000), 6U);  // /128: 816 kHz
  EXPECT_EQ(Spi::baud_rate_setting(64'000'000, 1'000'000), 5U);   // /64: exactly 1 MHz
  EXPECT_EQ(Spi::baud_rate_setting(64'000'001, 1'000'000), 6U);
  EXPECT_EQ(Spi::baud_rate_setting(2'000'000, 1'000'000), 0U);  // /2
  EXPECT_EQ(Spi::baud_rate_setting(256'000'000, 1'000'000), 7U);
  EXPECT_EQ(Spi::baud_rate_setting(256'000'001, 1'000'000), Spi::no_baud_rate);
  EXPECT_EQ(Spi::baud_rate_setting(0xFFFF'FFFF, 0xFFFF'FFFF), 0U);
  EXPECT_EQ(Spi::divider(6), 128U);
}

// Each kernel clock the RCC may report (rcc_test.cpp): PCLK2 on the DK2, HSI, CSI, the DK2's HSE, and one whose rate
// is unknown (0 Hz), which gets the slowest divider rather than the fastest.
TEST_F(SpiTest, StartsAtMostAt1MhzFromEachKernelClock) {
  constexpr struct {
    std::uint32_t kernel_hz;
    std::uint32_t mbr;
  } cases[] = {{104'500'000, 6}, {64'000'000, 5}, {4'000'000, 1}, {24'000'000, 4}, {0, 7}};
  for (const auto& [kernel_hz, mbr] : cases) {
    reg(Spi::cfg1) = 0x0007'0007;
    ASSERT_TRUE(spi.start(kernel_hz, 1'000'000)) << kernel_hz;
    EXPECT_EQ(reg(Spi::cfg1) >> Spi::baud_rate_shift, mbr) << kernel_hz;
    EXPECT_LE(kernel_hz / Spi::divider(mbr), 1'000'000U) << kernel_hz;
  }
}

TEST_F(SpiTest, StartsAMode3MasterOnBothStreams) {
  reg(Spi::cr1) = 0x1201;  // a previous firmware's transfer still running
  stream_reg(receive_stream, stream_cr) = 0x415;
  stream_reg(transmit_stream, stream_cr) = 0x455;
  start_at_pclk2();
  EXPECT_EQ(reg(Spi::cr1), 0x1000U);        // SSI, SPE off
  EXPECT_EQ(reg(Spi::ifcr), 0xFF8U);        // every flag cleared
  EXPECT_EQ(reg(Spi::cfg1), 0x6007'0007U);  // MBR = 6 (/128), CRCSIZE at reset, 8-bit frames, FTHLV = 0
  EXPECT_EQ(reg(Spi::cfg2), 0x8740'0000U);  // AFCNTR, SSM, CPOL, CPHA, MASTER; SSOE off, full duplex, Motorola
  EXPECT_EQ(reg(Spi::ier), 0x240U);         // OVRIE, MODFIE: the errors that stop a transfer short
  EXPECT_EQ(stream_reg(transmit_stream, stream_cr), 0x454U);  // memory to peripheral, bytes, MINC, TCIE, TEIE
  EXPECT_EQ(stream_reg(transmit_stream, par), static_cast<std::uint32_t>(spi_base() + 0x20));  // TXDR
  EXPECT_EQ(stream_reg(receive_stream, stream_cr), 0x414U);                                    // peripheral to memory
  EXPECT_EQ(stream_reg(receive_stream, par), static_cast<std::uint32_t>(spi_base() + 0x30));   // RXDR
  EXPECT_EQ(dmamux[8 + transmit_stream], 86U);
  EXPECT_EQ(dmamux[8 + receive_stream], 85U);
  // Both buffers inside the driver, apart.
  const auto object = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(&spi));
  for (const unsigned n : {transmit_stream, receive_stream}) {
    EXPECT_GE(stream_reg(n, m0ar), object);
    EXPECT_LE(stream_reg(n, m0ar) + 32, object + sizeof(spi));
  }
  EXPECT_GE(stream_reg(receive_stream, m0ar), stream_reg(transmit_stream, m0ar) + 32);
}

TEST_F(SpiTest, StartingAgainEndsATransferLeftRunning) {
  start_at_pclk2();
  ASSERT_TRUE(spi.transfer(sensor_read));
  start_at_pclk2();
  EXPECT_EQ(reg(Spi::cr1), 0x1000U);
  EXPECT_EQ(stream_reg(receive_stream, stream_cr), 0x414U);
  EXPECT_FALSE(spi.busy());
  EXPECT_TRUE(spi.transfer(sensor_read));
}

TEST_F(SpiTest, RefusesAKernelClockNoDividerBringsDown) {
  spi_registers.fill(0xAAAA'AAAA);
  EXPECT_FALSE(spi.start(300'000'000, 1'000'000));  // /256 would still give 1.17 MHz
  for (const std::uint32_t value : spi_registers) EXPECT_EQ(value, 0xAAAA'AAAAU);
  EXPECT_EQ(stream_reg(transmit_stream, stream_cr), 0U);
}

TEST_F(SpiTest, SensorReadInTheManualsOrderAndItsEnd) {
  start_at_pclk2();
  ASSERT_TRUE(spi.transfer(sensor_read));
  EXPECT_EQ(reg(Spi::cr2), 15U);                      // TSIZE
  EXPECT_EQ(reg(Spi::cfg1), 0x6007'0007U | 0xC000U);  // RXDMAEN, TXDMAEN
  EXPECT_EQ(stream_reg(receive_stream, ndtr), 15U);
  EXPECT_EQ(stream_reg(receive_stream, stream_cr), 0x415U);
  EXPECT_EQ(stream_reg(transmit_stream, ndtr), 15U);
  EXPECT_EQ(stream_reg(transmit_stream, stream_cr), 0x455U);
  EXPECT_EQ(dma[lifcr / 4], 0x3DU << 22);  // the transmit stream's flags, cleared last
  EXPECT_EQ(reg(Spi::cr1), 0x1201U);       // SSI, SPE, CSTART
  EXPECT_TRUE(spi.busy());
  const std::uint8_t* sent = memory_at(stream_reg(transmit_stream, m0ar));
  EXPECT_EQ(std::vector<std::uint8_t>(sent, sent + 15),
            std::vector<std::uint8_t>(sensor_read.begin(), sensor_read.end()));

  std::array<std::uint8_t, 15> answer{};
  for (std::size_t i = 0; i < answer.size(); ++i) answer[i] = static_cast<std::uint8_t>(0xF0 + i);
  finish_transfer(answer);
  const DmaFlags received = spi.on_receive_interrupt();
  EXPECT_TRUE(received.complete);
  EXPECT_FALSE(received.error);
  EXPECT_EQ(dma[lifcr / 4], receive_complete);  // the transmit stream's flag is its own handler's
  EXPECT_EQ(reg(Spi::ifcr), 0x258U);            // EOTC, TXTFC, OVRC, MODFC
  EXPECT_EQ(reg(Spi::cr1), 0x1000U);            // SPE off: the next transfer can be programmed
  EXPECT_EQ(reg(Spi::cfg1), 0x6007'0007U);      // DMA requests off
  EXPECT_FALSE(spi.busy());
  const std::span<const std::uint8_t> bytes = spi.received();
  EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin(), bytes.end()),
            std::vector<std::uint8_t>(answer.begin(), answer.end()));

  dma[lifcr / 4] = 0;
  const DmaFlags transmitted = spi.on_transmit_interrupt();
  EXPECT_TRUE(transmitted.complete);
  EXPECT_FALSE(transmitted.error);
  EXPECT_EQ(dma[lifcr / 4], transmit_complete);
  EXPECT_EQ(spi.errors().dma_errors, 0U);

  const std::array<std::uint8_t, 2> write_register{0x6B, 0x80};  // PWR_MGMT_1: device reset
  ASSERT_TRUE(spi.transfer(write_register));
  EXPECT_EQ(reg(Spi::cr2), 2U);
  EXPECT_EQ(stream_reg(receive_stream, ndtr), 2U);
  EXPECT_EQ(spi.received().size(), 2U);
}

TEST_F(SpiTest, RefusesWhileATransferRunsAndSizesItCannotTake) {
  const auto expect_refused = [this](std::span<const std::uint8_t> bytes) {
    const auto spi_before = spi_registers;
    const auto dma_before = dma;
    EXPECT_FALSE(spi.transfer(bytes));
    EXPECT_EQ(spi_registers, spi_before);
    EXPECT_EQ(dma, dma_before);
  };
  start_at_pclk2();
  ASSERT_TRUE(spi.transfer(sensor_read));
  const std::array<std::uint8_t, 2> who_am_i{0x75 | 0x80, 0};
  expect_refused(who_am_i);  // running
  finish_transfer(sensor_read);
  expect_refused(who_am_i);  // the streams are done, but only the receive interrupt ends the transfer
  EXPECT_TRUE(spi.busy());
  static_cast<void>(spi.on_receive_interrupt());
  EXPECT_FALSE(spi.busy());
  stream_reg(receive_stream, stream_cr) |= 1U;
  EXPECT_TRUE(spi.busy());
  expect_refused(who_am_i);  // the receive stream still stopping (as after an error)
  stream_reg(receive_stream, stream_cr) &= ~1U;
  stream_reg(transmit_stream, stream_cr) |= 1U;
  expect_refused(who_am_i);  // the transmit stream still stopping
  stream_reg(transmit_stream, stream_cr) &= ~1U;
  const std::array<std::uint8_t, 33> too_long{};
  expect_refused(too_long);
  expect_refused({});
  EXPECT_TRUE(spi.transfer(who_am_i));  // a refusal gives the SPI back
}

TEST_F(SpiTest, ATransmitErrorIsCountedAndEndsTheTransfer) {
  start_at_pclk2();
  ASSERT_TRUE(spi.transfer(sensor_read));
  stream_reg(transmit_stream, stream_cr) &= ~1U;  // a transfer error disables the stream
  dma[lisr / 4] = transmit_error;
  const DmaFlags flags = spi.on_transmit_interrupt();
  EXPECT_FALSE(flags.complete);
  EXPECT_TRUE(flags.error);
  EXPECT_EQ(dma[lifcr / 4], transmit_error);
  EXPECT_EQ(spi.errors().dma_errors, 1U);
  EXPECT_EQ(stream_reg(receive_stream, stream_cr), 0x414U);  // asked to stop, not waited for
  EXPECT_EQ(reg(Spi::cr1), 0x1000U);
  EXPECT_EQ(reg(Spi::cfg1), 0x6007'0007U);
  EXPECT_FALSE(spi.busy());
}

TEST_F(SpiTest, ReceiveErrorsAndSpiFaultsAreCounted) {
  start_at_pclk2();
  ASSERT_TRUE(spi.transfer(sensor_read));
  finish_transfer(sensor_read);
  reg(Spi::sr) |= Spi::overrun;
  const DmaFlags overrun = spi.on_receive_interrupt();
  EXPECT_TRUE(overrun.complete);
  EXPECT_TRUE(overrun.error);
  EXPECT_EQ(spi.errors().overruns, 1U);
  EXPECT_EQ(spi.errors().mode_faults, 0U);
  EXPECT_EQ(reg(Spi::ifcr), 0x258U);

  ASSERT_TRUE(spi.transfer(sensor_read));
  finish_transfer(sensor_read);
  reg(Spi::sr) |= Spi::mode_fault;
  EXPECT_TRUE(spi.on_receive_interrupt().error);
  EXPECT_EQ(spi.errors().overruns, 1U);
  EXPECT_EQ(spi.errors().mode_faults, 1U);
  EXPECT_EQ(spi.errors().dma_errors, 0U);

  reg(Spi::sr) = 0;
  ASSERT_TRUE(spi.transfer(sensor_read));
  stream_reg(receive_stream, stream_cr) &= ~1U;
  dma[lisr / 4] = receive_error;
  const DmaFlags failed = spi.on_receive_interrupt();
  EXPECT_FALSE(failed.complete);
  EXPECT_TRUE(failed.error);
  EXPECT_EQ(spi.errors().dma_errors, 1U);
  EXPECT_EQ(stream_reg(transmit_stream, stream_cr), 0x454U);
  EXPECT_EQ(reg(Spi::cr1), 0x1000U);
}

TEST_F(SpiTest, AnOverrunThatStopsTheSpiEndsTheTransferInItsOwnInterrupt) {
  start_at_pclk2();
  ASSERT_TRUE(spi.transfer(sensor_read));
  EXPECT_FALSE(spi.on_error_interrupt());  // no error flag: nothing ended
  EXPECT_TRUE(spi.busy());
  reg(Spi::sr) = Spi::overrun;  // the receive stream never completes
  EXPECT_TRUE(spi.on_error_interrupt());
  EXPECT_EQ(spi.errors().overruns, 1U);
  EXPECT_EQ(reg(Spi::cr1), 0x1000U);  // SPE off
  EXPECT_EQ(stream_reg(receive_stream, stream_cr), 0x414U);
  EXPECT_FALSE(spi.busy());
  // The same flag again without a transfer (ended meanwhile): cleared, nothing counted.
  reg(Spi::ifcr) = 0;
  EXPECT_FALSE(spi.on_error_interrupt());
  EXPECT_EQ(reg(Spi::ifcr), 0x240U);  // OVRC, MODFC
  EXPECT_EQ(spi.errors().overruns, 1U);
}

TEST_F(SpiTest, AnInterruptWithoutItsFlagsEndsNothing) {
  start_at_pclk2();
  ASSERT_TRUE(spi.transfer(sensor_read));
  dma[lisr / 4] = transmit_complete | 0x3DU;  // other streams' flags (3 and 0)
  const DmaFlags flags = spi.on_receive_interrupt();
  EXPECT_FALSE(flags.complete);
  EXPECT_FALSE(flags.error);
  EXPECT_EQ(reg(Spi::cr1), 0x1201U);
  EXPECT_EQ(dma[lifcr / 4], 0x3DU << 22);  // untouched since transfer()
  EXPECT_TRUE(spi.busy());
}

TEST_F(SpiTest, ATransferEndsOnce) {
  start_at_pclk2();
  ASSERT_TRUE(spi.transfer(sensor_read));
  finish_transfer(sensor_read);
  ASSERT_TRUE(spi.on_receive_interrupt().complete);
  // A late transfer error of the transmit stream, and a stale completion: counted and taken, nothing ended again.
  reg(Spi::cr1) = 0xAAAA'AAAA;
  reg(Spi::ifcr) = 0;
  dma[lisr / 4] = transmit_error | receive_complete;
  EXPECT_TRUE(spi.on_transmit_interrupt().error);
  EXPECT_TRUE(spi.on_receive_interrupt().complete);
  EXPECT_EQ(spi.errors().dma_errors, 1U);
  EXPECT_EQ(reg(Spi::cr1), 0xAAAA'AAAAU);
  EXPECT_EQ(reg(Spi::ifcr), 0U);
}

}  // namespace
}  // namespace duet::stm32mp15
