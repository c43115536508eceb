#pragma once
// The Arm CMSDK APB UART (QEMU's cmsdk-apb-uart): a one-byte transmit and receive buffer, no FIFO.

#include <cstdint>
#include <string_view>

namespace duet::mps2_an386 {

class CmsdkUart {
 public:
  explicit constexpr CmsdkUart(std::uintptr_t base) : base_(base) {}

  // Enables the transmitter at `baud_rate` derived from the peripheral clock. QEMU ignores the rate; hardware does not.
  void enable_transmitter(std::uint32_t peripheral_clock_hz, std::uint32_t baud_rate) const;

  // Writes every byte of `text`, waiting while the transmit buffer is full. Blocks: not for interrupt handlers.
  void write(std::string_view text) const;

  // Enables the receiver and its interrupt, raised when a byte has arrived.
  void enable_receive_interrupt() const;
  // Enables the transmit interrupt, raised when the transmit buffer has taken a byte and has room again.
  void enable_transmit_interrupt() const;
  // Puts `byte` in the transmit buffer unless it is full (false). Never waits.
  [[nodiscard]] bool try_write(std::uint8_t byte) const;
  // Acknowledges the transmit interrupt: before writing, or when there is nothing more to write.
  void clear_transmit_interrupt() const;
  // The received byte, if one is waiting; acknowledges the receive interrupt. Interrupt-safe, never waits.
  [[nodiscard]] bool read(char& byte) const;

 private:
  std::uintptr_t base_;
};

}  // namespace duet::mps2_an386
