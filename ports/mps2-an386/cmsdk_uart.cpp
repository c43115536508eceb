#include "duet/mps2_an386/cmsdk_uart.hpp"

#include "duet/cortex_m/registers.hpp"

namespace duet::mps2_an386 {
namespace {

using cortex_m::register32;

// Register offsets and bits (Arm CoreLink CMSDK, APB UART).
constexpr std::uintptr_t data = 0x00;
constexpr std::uintptr_t state = 0x04;
constexpr std::uintptr_t control = 0x08;
constexpr std::uintptr_t baud_divider = 0x10;
constexpr std::uintptr_t interrupt_status_and_clear = 0x0C;
constexpr std::uint32_t transmit_buffer_full = 1U << 0;
constexpr std::uint32_t receive_buffer_full = 1U << 1;
constexpr std::uint32_t transmit_enable = 1U << 0;
constexpr std::uint32_t receive_enable = 1U << 1;
constexpr std::uint32_t receive_interrupt_enable = 1U << 3;
constexpr std::uint32_t transmit_interrupt_enable = 1U << 2;
constexpr std::uint32_t transmit_interrupt = 1U << 0;
constexpr std::uint32_t receive_interrupt = 1U << 1;
constexpr std::uint32_t smallest_baud_divider = 16;  // the UART rejects smaller dividers

}  // namespace

void CmsdkUart::enable_transmitter(std::uint32_t peripheral_clock_hz, std::uint32_t baud_rate) const {
  const std::uint32_t divider = peripheral_clock_hz / baud_rate;
  register32(base_ + baud_divider) = divider < smallest_baud_divider ? smallest_baud_divider : divider;
  register32(base_ + control) = register32(base_ + control) | transmit_enable;
}

void CmsdkUart::write(std::string_view text) const {
  for (char character : text) {
    while ((register32(base_ + state) & transmit_buffer_full) != 0) {
    }
    register32(base_ + data) = static_cast<unsigned char>(character);
  }
}

void CmsdkUart::enable_receive_interrupt() const {
  register32(base_ + control) = register32(base_ + control) | receive_enable | receive_interrupt_enable;
}

void CmsdkUart::enable_transmit_interrupt() const {
  register32(base_ + control) = register32(base_ + control) | transmit_interrupt_enable;
}

void CmsdkUart::clear_transmit_interrupt() const {
  register32(base_ + interrupt_status_and_clear) = transmit_interrupt;
}

bool CmsdkUart::try_write(std::uint8_t byte) const {
  if ((register32(base_ + state) & transmit_buffer_full) != 0) return false;
  register32(base_ + data) = byte;
  return true;
}

bool CmsdkUart::read(char& byte) const {
  register32(base_ + interrupt_status_and_clear) = receive_interrupt;
  if ((register32(base_ + state) & receive_buffer_full) == 0) return false;
  byte = static_cast<char>(register32(base_ + data) & 0xFFU);
  return true;
}

}  // namespace duet::mps2_an386
