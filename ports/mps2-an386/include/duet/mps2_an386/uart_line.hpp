#pragma once
// A byte protocol (XCP's StreamTransport, the application channel's Endpoint, ...) on a CMSDK UART, moved by the
// UART's receive and transmit interrupts at the lowest priority: the protocol's work (an XCP command, say) runs below
// every task, and tasks only queue what they send and call kick(). On the board the same protocols run on RPMsg ttys;
// here QEMU's -serial options stand in for them.
//
// The protocol needs receive(std::span<const std::uint8_t>) for received bytes and transmit(std::span<std::uint8_t>)
// that frames what it has queued into the span and returns how many bytes it wrote (0: nothing to send).
//
// QEMU's UART sends a byte the moment it is written (a system call each), so a line may be limited to a number of
// bytes per base tick (limit_per_tick, new_tick): a burst of hundreds of bytes otherwise costs one tick of emulated
// time milliseconds of wall time, which a run paced to the wall clock has to catch up (docs/LINK.md, "Pacing").

#include <array>
#include <cstddef>
#include <cstdint>

#include "duet/cortex_m/interrupts.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_uart.hpp"

namespace duet::mps2_an386 {

// Only the line's two interrupts call serve(), both at one priority, so it never runs twice at once.
template <typename Protocol>
class UartLine {
 public:
  UartLine(CmsdkUart uart, unsigned receive_line, unsigned transmit_line)
      : uart_(uart), receive_line_(receive_line), transmit_line_(transmit_line) {}

  // Enables the UART and both its interrupts at the lowest priority. Call before enabling interrupts.
  void start() const {
    uart_.enable_transmitter(peripheral_clock_hz, baud_rate);
    uart_.enable_receive_interrupt();
    uart_.enable_transmit_interrupt();
    for (const unsigned line : {receive_line_, transmit_line_}) {
      cortex_m::set_interrupt_priority(line, lowest_priority);
      cortex_m::enable_interrupt(line);
    }
  }
  // From a task or any handler: there is something to send. Interrupt-safe, never waits.
  void kick() const { cortex_m::set_interrupt_pending(transmit_line_); }

  // At most `bytes` a base tick from now on (0: no limit, the default). Call before start().
  void limit_per_tick(std::uint32_t bytes) { bytes_per_tick_ = bytes; }
  // From the base tick's handler, more urgent than the line: a new tick's bytes may go; if serve() held some back,
  // its transmit interrupt comes again. (Should this come between serve()'s last byte and its holding back, the
  // bytes wait one more tick.)
  void new_tick() {
    ticks_ = ticks_ + 1U;
    if (held_back_) kick();
  }

  // From the line's receive and transmit interrupt handlers only.
  void serve(Protocol& protocol) {
    char byte = 0;
    while (uart_.read(byte)) {
      const auto received = static_cast<std::uint8_t>(byte);
      protocol.receive({&received, 1});
      ++bytes_received_;
    }
    uart_.clear_transmit_interrupt();
    held_back_ = false;
    for (;;) {
      if (sent_ == framed_) {
        framed_ = protocol.transmit(frames_);
        sent_ = 0;
        if (framed_ == 0) return;
      }
      if (bytes_per_tick_ != 0) {
        if (tick_seen_ != ticks_) {
          tick_seen_ = ticks_;
          sent_this_tick_ = 0;
        }
        if (sent_this_tick_ == bytes_per_tick_) {
          held_back_ = true;  // new_tick() kicks
          return;
        }
      }
      if (!uart_.try_write(frames_[sent_])) return;  // the transmit interrupt comes back when there is room
      ++sent_;
      ++sent_this_tick_;
      ++bytes_sent_;
    }
  }

  [[nodiscard]] std::uint32_t bytes_received() const { return bytes_received_; }
  [[nodiscard]] std::uint32_t bytes_sent() const { return bytes_sent_; }

 private:
  static constexpr unsigned lowest_priority = cortex_m::priority_levels - 1U;
  static constexpr std::uint32_t baud_rate = 115'200;  // QEMU ignores it; the board's RPMsg has none

  CmsdkUart uart_;
  unsigned receive_line_;
  unsigned transmit_line_;
  std::array<std::uint8_t, 512> frames_{};
  std::size_t framed_ = 0;
  std::size_t sent_ = 0;
  std::uint32_t bytes_received_ = 0;
  std::uint32_t bytes_sent_ = 0;
  std::uint32_t bytes_per_tick_ = 0;
  volatile std::uint32_t ticks_ = 0;  // written by new_tick() only, which preempts serve()
  volatile bool held_back_ = false;
  std::uint32_t tick_seen_ = 0;
  std::uint32_t sent_this_tick_ = 0;
};

}  // namespace duet::mps2_an386
