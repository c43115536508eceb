#pragma once
// A stream of DMA1/DMA2 with its DMAMUX1 request line (RM0436, DMA controller and DMAMUX): the stream moves `count`
// elements between a peripheral's data register and memory, one per request of the peripheral the DMAMUX routes to
// it; at the end it clears its EN bit itself and raises its transfer-complete flag (normal mode). Direct mode (no
// FIFO), single transfers, priority low: between streams of equal priority the lower stream number wins (RM0436 DMA,
// "Arbiter"), so SPI5's receive stream 2 goes before its transmit stream 3. Register level, no HAL; the addresses are
// the blocks' (fake register files in the PC's tests).

#include <cstdint>

#include "duet/cortex_m/registers.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t dma2_base = 0x4800'1000;
inline constexpr std::uintptr_t dmamux1_base = 0x4800'2000;

// The DMAMUX1 channel register (CxCR) that feeds DMA2 stream `stream`: DMA1's streams take channels 0-7, DMA2's 8-15.
constexpr std::uintptr_t dma2_request_line(unsigned stream) { return dmamux1_base + std::uintptr_t{4} * (8U + stream); }

// DMAMUX1 request inputs (RM0436 DMAMUX, "DMAMUX1 request line multiplexer inputs").
namespace dma_request {
inline constexpr std::uint32_t adc1 = 9;
inline constexpr std::uint32_t spi5_rx = 85;
inline constexpr std::uint32_t spi5_tx = 86;
}  // namespace dma_request

enum class DmaDirection : std::uint32_t { peripheral_to_memory = 0, memory_to_peripheral = 1 };
enum class DmaElement : std::uint32_t { byte = 0, half_word = 1, word = 2 };

// Addresses are the M4's (32 bits); `memory_increment` steps through a buffer, the peripheral side never moves.
struct DmaSetup {
  DmaDirection direction;
  std::uintptr_t peripheral_address;
  std::uintptr_t memory_address;
  DmaElement element;
  bool memory_increment;
  std::uint32_t request;
};

// What the stream's interrupt found (the thesis' DMA_flag_handler outputs).
struct DmaFlags {
  bool complete;
  bool error;
};

class DmaStream {
 public:
  // The controller's status and clear registers; stream 0's registers (stream n's are 0x18 n further).
  static constexpr std::uint32_t lisr = 0x00, hisr = 0x04, lifcr = 0x08, hifcr = 0x0C;
  static constexpr std::uint32_t cr = 0x10, ndtr = 0x14, par = 0x18, m0ar = 0x1C, fcr = 0x24;
  static constexpr std::uint32_t stream_spacing = 0x18;
  // SxCR
  static constexpr std::uint32_t enable = 1U << 0U;                              // EN
  static constexpr std::uint32_t transfer_error_interrupt = 1U << 2U;            // TEIE
  static constexpr std::uint32_t transfer_complete_interrupt = 1U << 4U;         // TCIE
  static constexpr unsigned direction_shift = 6;                                 // DIR
  static constexpr std::uint32_t memory_increment = 1U << 10U;                   // MINC
  static constexpr unsigned peripheral_size_shift = 11, memory_size_shift = 13;  // PSIZE, MSIZE
  // A stream's flags in LISR/HISR, and their clear bits in LIFCR/HIFCR, from the stream's flag offset.
  static constexpr std::uint32_t transfer_error_flag = 1U << 3U;     // TEIF
  static constexpr std::uint32_t transfer_complete_flag = 1U << 5U;  // TCIF
  static constexpr std::uint32_t all_flags = 0x3D;                   // FEIF, DMEIF, TEIF, HTIF, TCIF

  // Stream `stream` (0-7) of the controller at `dma_base`, fed by the DMAMUX channel register at `request_line`.
  constexpr DmaStream(std::uintptr_t dma_base, unsigned stream, std::uintptr_t request_line)
      : dma_base_(dma_base),
        stream_base_(dma_base + std::uintptr_t{stream_spacing} * stream),
        flag_shift_(flag_shifts[stream % 4U]),
        high_(stream >= 4),
        request_line_(request_line) {}

  // Sets the stream up, interrupts on completion and on errors, in RM0436's "Stream configuration procedure" order
  // (the count comes with start()). False, nothing touched, while the stream is enabled: its registers are
  // read-only then, and the stream may take a while to stop (this never waits for it).
  [[nodiscard]] bool configure(const DmaSetup& setup) const {
    if (enabled()) return false;
    write(par, static_cast<std::uint32_t>(setup.peripheral_address));
    write(m0ar, static_cast<std::uint32_t>(setup.memory_address));
    write_at(request_line_, setup.request);  // DMAREQ_ID; no synchronisation, no event generation
    write(fcr, 0);                           // DMDIS = 0: direct mode
    const auto size = static_cast<std::uint32_t>(setup.element);
    write(cr, static_cast<std::uint32_t>(setup.direction) << direction_shift |
                  (setup.memory_increment ? memory_increment : 0U) | size << peripheral_size_shift |
                  size << memory_size_shift | transfer_complete_interrupt | transfer_error_interrupt);
    return true;
  }

  // Moves `count` elements (1-65535). False, nothing touched, while the stream is still enabled or for a count
  // NDTR cannot hold. Interrupt-safe with respect to the other streams (it writes only this stream's bits).
  [[nodiscard]] bool start(std::uint32_t count) const {
    if (enabled() || count == 0 || count > 0xFFFF) return false;
    arm(count);
    return true;
  }
  // start() without its checks, for a driver that checked enabled() and the count itself and must enable the
  // stream between writes of its own (SPI: RM0436's order of DMA requests and streams).
  void arm(std::uint32_t count) const {
    write_at(flag_clear(), all_flags << flag_shift_);  // RM0436: the stream's flags must be clear before EN is set
    write(ndtr, count);
    cortex_m::modify32(stream_base_ + cr, 0, enable);
  }

  // In the stream's interrupt: its transfer-complete and transfer-error flags, each cleared if it was set; the
  // other streams' flags and this stream's others are left alone.
  [[nodiscard]] DmaFlags take_flags() const {
    const std::uint32_t seen = cortex_m::register32(dma_base_ + (high_ ? hisr : lisr)) >> flag_shift_ &
                               (transfer_complete_flag | transfer_error_flag);
    if (seen != 0) write_at(flag_clear(), seen << flag_shift_);
    return {(seen & transfer_complete_flag) != 0, (seen & transfer_error_flag) != 0};
  }

  // Asks the stream to stop; it finishes the element under way first, so enabled() may stay true for a moment.
  void disable() const { cortex_m::modify32(stream_base_ + cr, enable, 0); }
  [[nodiscard]] bool enabled() const { return (read(cr) & enable) != 0; }

 private:
  // Streams 0-3 (LISR) and 4-7 (HISR) keep their flags at these bits.
  static constexpr unsigned flag_shifts[4] = {0, 6, 16, 22};

  [[nodiscard]] std::uintptr_t flag_clear() const { return dma_base_ + (high_ ? hifcr : lifcr); }
  // The stream's own registers, by their stream 0 offsets.
  [[nodiscard]] std::uint32_t read(std::uint32_t offset) const { return cortex_m::register32(stream_base_ + offset); }
  void write(std::uint32_t offset, std::uint32_t value) const { cortex_m::register32(stream_base_ + offset) = value; }
  static void write_at(std::uintptr_t address, std::uint32_t value) { cortex_m::register32(address) = value; }

  std::uintptr_t dma_base_;
  std::uintptr_t stream_base_;
  unsigned flag_shift_;
  bool high_;
  std::uintptr_t request_line_;
};

}  // namespace duet::stm32mp15
