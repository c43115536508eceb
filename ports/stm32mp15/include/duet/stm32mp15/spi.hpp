#pragma once
// An SPI master, full duplex by DMA (RM0436, SPI; the STM32MP15's SPI is the newer IP: transfer size in CR2.TSIZE,
// CSTART, FIFOs): the robot's MPU6500 on SPI5, DMA2 stream 3 transmitting and stream 2 receiving (thesis 5.5,
// SPI_DMA_Transmit, SPI_DMA_Receive, DMA_flag_handler). 8-bit frames, software slave management: the chip select
// is a GPIO the board drives, low before transfer() and high once on_receive_interrupt() reports the end.
//
// Mode 3 (CPOL = 1, CPHA = 1): the MPU6500 takes mode 0 or 3 (it latches on the rising edge and shifts on the
// falling one); its data sheet draws SCLK idling high, and with the pins kept driven between transfers (AFCNTR)
// the first edge after the chip select falls is a shifting edge, never a latching one.
//
// Register level, no HAL; the addresses are the blocks' (fake register files in the PC's tests). The object holds
// the DMA buffers: give it static storage in the M4's SRAM and never move it. The robot's:
//   SpiMaster<> imu{spi5_base, DmaStream{dma2_base, 3, dma2_request_line(3)}, dma_request::spi5_tx,
//                   DmaStream{dma2_base, 2, dma2_request_line(2)}, dma_request::spi5_rx};

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/cortex_m/registers.hpp"
#include "duet/stm32mp15/dma.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t spi5_base = 0x4400'9000;

// Counts of what ended transfers early or spoiled them.
struct SpiErrors {
  std::uint32_t overruns = 0;     // SR.OVR: a received frame was lost
  std::uint32_t mode_faults = 0;  // SR.MODF: impossible with SSM = 1 and SSI = 1 unless misconfigured
  std::uint32_t dma_errors = 0;   // a stream's TEIF
};

// `Capacity` bytes at most per transfer: 15 for the MPU6500's sensor read, 32 is plenty.
template <std::size_t Capacity = 32>
class SpiMaster {
  static_assert(Capacity >= 1 && Capacity <= 0xFFFF, "TSIZE and NDTR count at most 65535 frames");

 public:
  static constexpr std::uint32_t cr1 = 0x00, cr2 = 0x04, cfg1 = 0x08, cfg2 = 0x0C, ier = 0x10, sr = 0x14, ifcr = 0x18,
                                 txdr = 0x20, rxdr = 0x30;
  // CR1
  static constexpr std::uint32_t enable = 1U << 0U;            // SPE
  static constexpr std::uint32_t start_transfer = 1U << 9U;    // CSTART
  static constexpr std::uint32_t internal_select = 1U << 12U;  // SSI: the slave-select level SSM feeds the master,
                                                               // high so that it sees no mode fault
  // CFG1 (FTHLV = 0: a DMA request per frame)
  static constexpr std::uint32_t frame_8_bits = 7U << 0U;     // DSIZE = bits - 1
  static constexpr std::uint32_t receive_dma = 1U << 14U;     // RXDMAEN
  static constexpr std::uint32_t transmit_dma = 1U << 15U;    // TXDMAEN
  static constexpr std::uint32_t crc_size_reset = 7U << 16U;  // CRCSIZE at its reset value (CRC off)
  static constexpr unsigned baud_rate_shift = 28;             // MBR: the kernel clock / 2^(MBR + 1)
  static constexpr std::uint32_t slowest_baud_rate = 7;       // MBR for the divider 256
  static constexpr std::uint32_t no_baud_rate = 8;            // baud_rate_setting(): no MBR is slow enough
  // CFG2
  static constexpr std::uint32_t master = 1U << 22U;           // MASTER
  static constexpr std::uint32_t clock_phase = 1U << 24U;      // CPHA
  static constexpr std::uint32_t clock_polarity = 1U << 25U;   // CPOL
  static constexpr std::uint32_t software_select = 1U << 26U;  // SSM
  static constexpr std::uint32_t keep_pins = 1U << 31U;        // AFCNTR: the SPI drives its pins while SPE = 0
  // SR flags and their IFCR clear bits (EOTC, TXTFC, OVRC, MODFC) at the same positions
  static constexpr std::uint32_t end_of_transfer = 1U << 3U;  // EOT
  static constexpr std::uint32_t transfer_filled = 1U << 4U;  // TXTF
  static constexpr std::uint32_t overrun = 1U << 6U;          // OVR
  static constexpr std::uint32_t mode_fault = 1U << 9U;       // MODF
  // IER: the SPI's own interrupt, for the errors that stop a transfer before the receive stream completes
  static constexpr std::uint32_t overrun_interrupt = 1U << 6U;     // OVRIE
  static constexpr std::uint32_t mode_fault_interrupt = 1U << 9U;  // MODFIE
  static constexpr std::uint32_t all_flags = 0xFF8;                // IFCR: EOTC .. SUSPC

  // `base`: the SPI's registers; `transmit`, `receive`: its DMA streams, with the DMAMUX requests that feed them.
  constexpr SpiMaster(std::uintptr_t base, DmaStream transmit, std::uint32_t transmit_request, DmaStream receive,
                      std::uint32_t receive_request)
      : base_(base),
        transmit_(transmit),
        receive_(receive),
        transmit_request_(transmit_request),
        receive_request_(receive_request) {}
  SpiMaster(const SpiMaster&) = delete;
  SpiMaster& operator=(const SpiMaster&) = delete;

  // The smallest MBR whose divider 2^(MBR + 1) brings `kernel_clock_hz` down to at most `max_clock_hz`, or
  // no_baud_rate when even 256 does not. A kernel clock not known (0 Hz) gets the slowest divider, 256, the safest
  // guess, never the fastest.
  static constexpr std::uint32_t baud_rate_setting(std::uint32_t kernel_clock_hz, std::uint32_t max_clock_hz) {
    if (kernel_clock_hz == 0) return slowest_baud_rate;
    for (std::uint32_t setting = 0; setting < no_baud_rate; ++setting) {
      if (kernel_clock_hz <= std::uint64_t{max_clock_hz} << (setting + 1U)) return setting;
    }
    return no_baud_rate;
  }

  // The divider of MBR `setting`.
  static constexpr std::uint32_t divider(std::uint32_t setting) { return 2U << setting; }

  // At start-up, before the DMA interrupts are on: master, 8-bit frames, mode 3, the fastest clock of at most
  // `max_clock_hz` (the MPU6500 takes 1 MHz for every register) from the SPI's `kernel_clock_hz` (0: not known, the
  // slowest divider), both streams on the driver's buffers. Stops whatever a previous firmware left running. False,
  // nothing touched, when even the divider 256 is too fast; false when a stream has not stopped yet (try again).
  [[nodiscard]] bool start(std::uint32_t kernel_clock_hz, std::uint32_t max_clock_hz) {
    const std::uint32_t setting = baud_rate_setting(kernel_clock_hz, max_clock_hz);
    if (setting == no_baud_rate) return false;
    write(cr1, internal_select);  // SPE = 0: RM0436 lets CFG1, CFG2 and CR2 be written only then
    transmit_.disable();
    receive_.disable();
    write(ifcr, all_flags);
    write(cfg1, setting << baud_rate_shift | crc_size_reset | frame_8_bits);
    write(cfg2, keep_pins | software_select | clock_polarity | clock_phase | master);
    write(ier, overrun_interrupt | mode_fault_interrupt);
    state_.store(State::idle, std::memory_order_release);
    return transmit_.configure({.direction = DmaDirection::memory_to_peripheral,
                                .peripheral_address = base_ + txdr,
                                .memory_address = reinterpret_cast<std::uintptr_t>(transmit_buffer_.data()),
                                .element = DmaElement::byte,
                                .memory_increment = true,
                                .request = transmit_request_}) &&
           receive_.configure({.direction = DmaDirection::peripheral_to_memory,
                               .peripheral_address = base_ + rxdr,
                               .memory_address = reinterpret_cast<std::uintptr_t>(receive_buffer_.data()),
                               .element = DmaElement::byte,
                               .memory_increment = true,
                               .request = receive_request_});
  }

  // A transfer started and not yet ended by the handlers below (HAL_BUSY), or a stream still stopping.
  [[nodiscard]] bool busy() const {
    return state_.load(std::memory_order_acquire) != State::idle || transmit_.enabled() || receive_.enabled();
  }

  // Sends `bytes` (1 to Capacity) and receives as many meanwhile. False, nothing touched, while busy() or for a
  // size it cannot take. Interrupt-safe: of two tasks calling it at once, one gets the SPI.
  [[nodiscard]] bool transfer(std::span<const std::uint8_t> bytes) {
    if (bytes.empty() || bytes.size() > Capacity) return false;
    State idle = State::idle;
    if (!state_.compare_exchange_strong(idle, State::running, std::memory_order_acquire)) return false;
    if (transmit_.enabled() || receive_.enabled()) {  // still stopping after an error: DmaStream::arm() needs EN = 0
      state_.store(State::idle, std::memory_order_release);
      return false;
    }
    const auto count = static_cast<std::uint32_t>(bytes.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) transmit_buffer_[i] = bytes[i];
    count_ = count;
    std::atomic_signal_fence(std::memory_order_release);  // the bytes are in memory before a stream may read them
    write(cr2, count);                                    // TSIZE
    // RM0436 SPI, "Communication using DMA": receive requests, the streams, transmit requests, SPE, then CSTART.
    cortex_m::modify32(base_ + cfg1, 0, receive_dma);
    receive_.arm(count);
    transmit_.arm(count);
    cortex_m::modify32(base_ + cfg1, 0, transmit_dma);
    write(cr1, internal_select | enable);
    write(cr1, internal_select | enable | start_transfer);
    return true;
  }

  // DMA2_Stream3's handler: takes the transmit stream's flags; a transfer error ends the transfer.
  DmaFlags on_transmit_interrupt() {
    const DmaFlags flags = transmit_.take_flags();
    if (flags.error) {
      dma_errors_.fetch_add(1, std::memory_order_relaxed);
      static_cast<void>(end_transfer());
    }
    return flags;
  }

  // DMA2_Stream2's handler: takes the receive stream's flags; on completion or an error it ends the transfer (the
  // next one may start), counting the SPI's error flags. `complete` without `error`: received() holds the bytes.
  // Either handler may preempt the other, and a task calling transfer() may preempt both.
  DmaFlags on_receive_interrupt() {
    const DmaFlags flags = receive_.take_flags();
    if (!flags.complete && !flags.error) return flags;
    if (flags.error) dma_errors_.fetch_add(1, std::memory_order_relaxed);
    const bool spi_error = end_transfer();
    return {flags.complete, flags.error || spi_error};
  }

  // The SPI's own handler (SPI5): an overrun or a mode fault stops the SPI before the receive stream completes, so
  // nothing else would end that transfer. True if it ended one (counted); flags without a transfer are cleared.
  bool on_error_interrupt() {
    if ((read(sr) & (overrun | mode_fault)) == 0) return false;
    if (end_transfer()) return true;
    write(ifcr, overrun | mode_fault);  // a DMA handler ended the transfer first, or there was none
    return false;
  }

  // The bytes the last transfer received, byte 0 clocked in while the first byte (the MPU6500's address) went out.
  // Valid from its completion until the next transfer().
  [[nodiscard]] std::span<const std::uint8_t> received() const {
    std::atomic_signal_fence(std::memory_order_acquire);  // the stream wrote them behind the compiler's back
    return {receive_buffer_.data(), count_};
  }
  [[nodiscard]] SpiErrors errors() const {
    return {overruns_.load(std::memory_order_relaxed), mode_faults_.load(std::memory_order_relaxed),
            dma_errors_.load(std::memory_order_relaxed)};
  }

 private:
  // Who has the SPI: transfer() takes it (idle to running); the handler that ends the transfer takes it over (running
  // to ending) and gives it back only after its last register write, so that neither the other handler nor a task
  // calling transfer() can come in between.
  enum class State : std::uint8_t { idle, running, ending };
  static_assert(std::atomic<State>::is_always_lock_free && std::atomic<std::uint32_t>::is_always_lock_free,
                "shared by handlers and tasks without a lock");

  // RM0436 SPI, closing a communication using DMA: the streams off, the SPI off (its flags cleared first, as the
  // HAL does), then its DMA requests off. Never waits: the receive stream's completion means every frame is in.
  // Whether the SPI had lost a frame or seen a mode fault; false, nothing done, if the transfer is not running.
  bool end_transfer() {
    State running = State::running;
    if (!state_.compare_exchange_strong(running, State::ending, std::memory_order_acquire)) return false;
    const std::uint32_t status = read(sr);
    if ((status & overrun) != 0) overruns_.fetch_add(1, std::memory_order_relaxed);
    if ((status & mode_fault) != 0) mode_faults_.fetch_add(1, std::memory_order_relaxed);
    transmit_.disable();
    receive_.disable();
    write(ifcr, end_of_transfer | transfer_filled | overrun | mode_fault);
    write(cr1, internal_select);
    cortex_m::modify32(base_ + cfg1, receive_dma | transmit_dma, 0);  // CFG1 is read-only while SPE = 1
    state_.store(State::idle, std::memory_order_release);
    return (status & (overrun | mode_fault)) != 0;
  }

  [[nodiscard]] std::uint32_t read(std::uint32_t offset) const { return cortex_m::register32(base_ + offset); }
  void write(std::uint32_t offset, std::uint32_t value) const { cortex_m::register32(base_ + offset) = value; }

  std::uintptr_t base_;
  DmaStream transmit_;
  DmaStream receive_;
  std::uint32_t transmit_request_;
  std::uint32_t receive_request_;
  std::array<std::uint8_t, Capacity> transmit_buffer_{};
  std::array<std::uint8_t, Capacity> receive_buffer_{};
  std::size_t count_ = 0;
  std::atomic<State> state_{State::idle};
  std::atomic<std::uint32_t> overruns_{0};
  std::atomic<std::uint32_t> mode_faults_{0};
  std::atomic<std::uint32_t> dma_errors_{0};
};

}  // namespace duet::stm32mp15
