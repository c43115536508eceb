#pragma once
// An input-capture channel as the thesis configures TIM2, TIM4 and TIM5: a 16-bit counter at 1 MHz (prescaler
// 208 - 1 from 208.87 MHz), reset to 0 at every capture, started at time 0. What a capture returns is the counter:
// the whole microseconds since the previous capture, modulo 65536.

#include <cstdint>

namespace duet::plant::balbot {

using Nanoseconds = std::int64_t;

class CaptureTimer {
 public:
  void capture(Nanoseconds now, bool rising) {
    const Nanoseconds tick = now / 1000;  // the counter counts on a fixed 1 us grid
    count_ = static_cast<std::uint16_t>(static_cast<std::uint64_t>(tick - last_tick_) & 0xFFFFU);
    last_tick_ = tick;
    rising_ = rising;
  }
  [[nodiscard]] std::uint16_t count() const { return count_; }
  [[nodiscard]] bool rising() const { return rising_; }

 private:
  Nanoseconds last_tick_ = 0;
  std::uint16_t count_ = 0;
  bool rising_ = false;
};

}  // namespace duet::plant::balbot
