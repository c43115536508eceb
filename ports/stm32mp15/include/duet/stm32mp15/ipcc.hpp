#pragma once
// The IPCC's doorbells, from the Cortex-M4's side (processor 2; RM0436, IPCC): a channel's flag set by one processor
// interrupts the other, which clears it when it has taken the message. Channels (0-based): 0 tells Linux of used
// buffers in vring0 (and Linux tells us it returned some), 1 tells us of a message in vring1, 2 is Linux's shutdown
// request and 3 its detach request, both to be acknowledged by clearing them. A channel's flag holds IPCC_RX1
// pending until it is cleared or the channel masked, so the handler masks what it takes and unmasks it once served
// (as ST's HAL does): a flag that cannot be cleared yet then never keeps the interrupt running. C2MR is the M4's own
// register; Linux writes only C1MR. Register level, no HAL; `base` is the block's address (a fake register file in
// the PC's tests). Never waits: a doorbell still ringing is reported.

#include <cstdint>

#include "duet/cortex_m/registers.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t ipcc_base = 0x4C00'1000;

namespace ipcc_channel {
inline constexpr unsigned vring0 = 0;
inline constexpr unsigned vring1 = 1;
inline constexpr unsigned shutdown = 2;
inline constexpr unsigned detach = 3;
}  // namespace ipcc_channel

class Ipcc {
 public:
  static constexpr std::uint32_t c1cr = 0x00, c1mr = 0x04, c1scr = 0x08, c1toc2sr = 0x0C;
  static constexpr std::uint32_t c2cr = 0x10, c2mr = 0x14, c2scr = 0x18, c2toc1sr = 0x1C;
  static constexpr std::uint32_t receive_interrupt = 1U << 0U;    // RXOIE
  static constexpr std::uint32_t transmit_interrupt = 1U << 16U;  // TXFIE
  static constexpr std::uint32_t all_channels = 0x3F;

  explicit constexpr Ipcc(std::uintptr_t base = ipcc_base) : base_(base) {}

  // Interrupts off, every channel masked and its flag cleared (whatever a previous firmware left); then the receive
  // interrupt on. No channel interrupts until unmask_receive() lets it.
  void start() const {
    write(c2cr, 0);
    write(c2mr, all_channels | all_channels << 16U);
    write(c2scr, all_channels);
    write(c2cr, receive_interrupt);
  }

  // The channels (a bit per channel) whose doorbells interrupt, or no longer do; the free-channel masks stay as they
  // are. Read-modify-writes of C2MR: from one context at a time.
  void unmask_receive(std::uint32_t channels) const { write(c2mr, read(c2mr) & ~(channels & all_channels)); }
  void mask_receive(std::uint32_t channels) const { write(c2mr, read(c2mr) | (channels & all_channels)); }

  // The channels Linux has rung and that are unmasked: what holds the IPCC_RX1 interrupt pending.
  [[nodiscard]] std::uint32_t pending() const { return read(c1toc2sr) & ~read(c2mr) & all_channels; }
  // The channels Linux has rung, masked or not.
  [[nodiscard]] std::uint32_t rung() const { return read(c1toc2sr) & all_channels; }
  // The message of `channel` is taken: Linux may ring it again.
  void acknowledge(unsigned channel) const { write(c2scr, 1U << channel); }

  // Rings `channel` for Linux; false while it still rings from last time (Linux has not taken it yet).
  [[nodiscard]] bool ring(unsigned channel) const {
    if ((read(c2toc1sr) & 1U << channel) != 0) return false;
    write(c2scr, 1U << (16U + channel));
    return true;
  }

 private:
  [[nodiscard]] std::uint32_t read(std::uint32_t offset) const { return cortex_m::register32(base_ + offset); }
  void write(std::uint32_t offset, std::uint32_t value) const { cortex_m::register32(base_ + offset) = value; }

  std::uintptr_t base_;
};

}  // namespace duet::stm32mp15
