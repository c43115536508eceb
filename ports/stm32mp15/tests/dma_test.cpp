// DMA streams against fake register files (a DMA controller and DMAMUX1): the set-up RM0436's stream configuration
// procedure asks for, starting with the stream's flags cleared, refusals while a stream is enabled, and every
// stream's flags read and cleared at its own bits of LISR/HISR and LIFCR/HIFCR (thesis figures A.9, A.13-A.15).
#include "duet/stm32mp15/dma.hpp"

#include <gtest/gtest.h>

#include <array>

namespace duet::stm32mp15 {
namespace {

constexpr std::uint32_t lisr = 0x00, hisr = 0x04, lifcr = 0x08, hifcr = 0x0C;
constexpr std::uint32_t cr = 0x10, ndtr = 0x14, par = 0x18, m0ar = 0x1C, fcr = 0x24;

class DmaTest : public ::testing::Test {
 protected:
  std::uint32_t& reg(std::uint32_t offset) { return dma[offset / 4]; }
  std::uint32_t& stream_reg(unsigned index, std::uint32_t offset) { return reg(offset + 0x18 * index); }
  DmaStream stream(unsigned n) {
    return DmaStream{reinterpret_cast<std::uintptr_t>(dma.data()), n, reinterpret_cast<std::uintptr_t>(&dmamux[8 + n])};
  }
  std::array<std::uint32_t, 0xD0 / 4> dma{};
  std::array<std::uint32_t, 16> dmamux{};
};

TEST_F(DmaTest, Dma2StreamsTakeDmamux1ChannelsFromEight) {
  EXPECT_EQ(dma2_request_line(0), 0x4800'2020U);
  EXPECT_EQ(dma2_request_line(2), 0x4800'2028U);  // SPI5 receive
  EXPECT_EQ(dma2_request_line(3), 0x4800'202CU);  // SPI5 transmit
  EXPECT_EQ(dma2_request_line(4), 0x4800'2030U);  // ADC1
  EXPECT_EQ(dma_request::spi5_rx, 85U);
  EXPECT_EQ(dma_request::spi5_tx, 86U);
  EXPECT_EQ(dma_request::adc1, 9U);
}

TEST_F(DmaTest, TransmitStreamOfBytesFromMemory) {
  stream_reg(3, fcr) = 0x21;  // reset value: FIFO empty, threshold 1/2
  std::array<std::uint8_t, 4> buffer{};
  ASSERT_TRUE(stream(3).configure({.direction = DmaDirection::memory_to_peripheral,
                                   .peripheral_address = 0x4400'9020,
                                   .memory_address = reinterpret_cast<std::uintptr_t>(buffer.data()),
                                   .element = DmaElement::byte,
                                   .memory_increment = true,
                                   .request = dma_request::spi5_tx}));
  EXPECT_EQ(stream_reg(3, par), 0x4400'9020U);
  EXPECT_EQ(stream_reg(3, m0ar), static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(buffer.data())));
  EXPECT_EQ(dmamux[11], 86U);            // DMAREQ_ID alone: no synchronisation, no events
  EXPECT_EQ(stream_reg(3, fcr), 0U);     // direct mode
  EXPECT_EQ(stream_reg(3, cr), 0x454U);  // DIR = 01, MINC, byte sizes, TCIE, TEIE; not enabled
  EXPECT_EQ(stream_reg(2, cr), 0U);
  EXPECT_EQ(dmamux[10], 0U);
}

TEST_F(DmaTest, ReceiveStreamOfHalfWordsIntoMemory) {
  ASSERT_TRUE(stream(4).configure({.direction = DmaDirection::peripheral_to_memory,
                                   .peripheral_address = 0x4800'3040,
                                   .memory_address = 0x1002'0000,
                                   .element = DmaElement::half_word,
                                   .memory_increment = true,
                                   .request = dma_request::adc1}));
  EXPECT_EQ(stream_reg(4, par), 0x4800'3040U);
  EXPECT_EQ(stream_reg(4, m0ar), 0x1002'0000U);
  EXPECT_EQ(dmamux[12], 9U);
  EXPECT_EQ(stream_reg(4, cr), 0x2C14U);  // DIR = 00, MINC, PSIZE = MSIZE = 01, TCIE, TEIE
}

TEST_F(DmaTest, StartClearsTheStreamsFlagsThenCountsThenEnables) {
  stream_reg(3, cr) = 0x454;
  ASSERT_TRUE(stream(3).start(15));
  EXPECT_EQ(reg(lifcr), 0x3DU << 22);  // CFEIF3, CDMEIF3, CTEIF3, CHTIF3, CTCIF3
  EXPECT_EQ(stream_reg(3, ndtr), 15U);
  EXPECT_EQ(stream_reg(3, cr), 0x455U);
  stream_reg(4, cr) = 0x2C14;
  ASSERT_TRUE(stream(4).start(100));
  EXPECT_EQ(reg(hifcr), 0x3DU);  // stream 4's flags are HISR's first
  EXPECT_EQ(stream_reg(4, ndtr), 100U);
  EXPECT_EQ(stream_reg(4, cr), 0x2C15U);
}

TEST_F(DmaTest, AnEnabledStreamIsNeitherReconfiguredNorRestarted) {
  stream_reg(2, cr) = 0x415;  // still enabled: EN may take a while to clear, and nothing waits for it
  stream_reg(2, ndtr) = 3;
  EXPECT_FALSE(stream(2).configure({.direction = DmaDirection::memory_to_peripheral,
                                    .peripheral_address = 1,
                                    .memory_address = 2,
                                    .element = DmaElement::word,
                                    .memory_increment = false,
                                    .request = 1}));
  EXPECT_FALSE(stream(2).start(15));
  EXPECT_EQ(stream_reg(2, cr), 0x415U);
  EXPECT_EQ(stream_reg(2, ndtr), 3U);
  EXPECT_EQ(stream_reg(2, par), 0U);
  EXPECT_EQ(dmamux[10], 0U);
  EXPECT_EQ(reg(lifcr), 0U);
  EXPECT_TRUE(stream(2).enabled());
  stream(2).disable();
  EXPECT_EQ(stream_reg(2, cr), 0x414U);
  EXPECT_FALSE(stream(2).enabled());
}

TEST_F(DmaTest, CountsNdtrCannotHoldAreRefused) {
  EXPECT_FALSE(stream(5).start(0));
  EXPECT_FALSE(stream(5).start(0x1'0000));
  EXPECT_EQ(stream_reg(5, cr), 0U);
  EXPECT_EQ(reg(hifcr), 0U);
  EXPECT_TRUE(stream(5).start(0xFFFF));
}

// Where RM0436 (and the thesis' figure A.14) puts each stream's TCIF and TEIF: streams 0-3 in LISR, 4-7 in HISR.
struct FlagBits {
  std::uint32_t status, clear;
  unsigned complete, error;
};
constexpr std::array<FlagBits, 8> flag_bits{{{lisr, lifcr, 5, 3},
                                             {lisr, lifcr, 11, 9},
                                             {lisr, lifcr, 21, 19},
                                             {lisr, lifcr, 27, 25},
                                             {hisr, hifcr, 5, 3},
                                             {hisr, hifcr, 11, 9},
                                             {hisr, hifcr, 21, 19},
                                             {hisr, hifcr, 27, 25}}};

TEST_F(DmaTest, EachStreamTakesAndClearsOnlyItsOwnCompleteAndErrorFlags) {
  for (unsigned n = 0; n < 8; ++n) {
    SCOPED_TRACE(n);
    const FlagBits& bits = flag_bits[n];
    const std::uint32_t other_status = bits.status == lisr ? hisr : lisr;
    const std::uint32_t other_clear = bits.clear == lifcr ? hifcr : lifcr;
    dma.fill(0);
    reg(bits.status) = 0x0F7D'0F7D;  // every flag of every stream
    reg(other_status) = 0x0F7D'0F7D;
    const DmaFlags both = stream(n).take_flags();
    EXPECT_TRUE(both.complete);
    EXPECT_TRUE(both.error);
    EXPECT_EQ(reg(bits.clear), 1U << bits.complete | 1U << bits.error);  // not HTIF, DMEIF, FEIF, nor others'
    EXPECT_EQ(reg(other_clear), 0U);

    reg(bits.clear) = 0;
    reg(bits.status) = 1U << bits.complete;
    const DmaFlags complete = stream(n).take_flags();
    EXPECT_TRUE(complete.complete);
    EXPECT_FALSE(complete.error);
    EXPECT_EQ(reg(bits.clear), 1U << bits.complete);

    reg(bits.clear) = 0;
    reg(bits.status) = 0x0F7D'0F7D & ~(1U << bits.complete | 1U << bits.error);  // the others' flags only
    const DmaFlags none = stream(n).take_flags();
    EXPECT_FALSE(none.complete);
    EXPECT_FALSE(none.error);
    EXPECT_EQ(reg(bits.clear), 0U);  // a flag never seen is never cleared
  }
}

TEST_F(DmaTest, StartClearsAllFiveFlagsOfEveryStreamAtItsOwnBits) {
  constexpr std::array<std::uint32_t, 8> cleared{0x3DU, 0x3DU << 6, 0x3DU << 16, 0x3DU << 22,
                                                 0x3DU, 0x3DU << 6, 0x3DU << 16, 0x3DU << 22};
  for (unsigned n = 0; n < 8; ++n) {
    SCOPED_TRACE(n);
    dma.fill(0);
    ASSERT_TRUE(stream(n).start(1));
    EXPECT_EQ(reg(n < 4 ? lifcr : hifcr), cleared[n]);
    EXPECT_EQ(reg(n < 4 ? hifcr : lifcr), 0U);
    EXPECT_EQ(stream_reg(n, cr), 1U);
  }
}

}  // namespace
}  // namespace duet::stm32mp15
