#pragma once
// TIM1 (advanced-control) and TIM2/TIM4/TIM5 (general-purpose) for the robot (RM0436, TIM1/TIM8 and TIM2-TIM5; the
// thesis' section 5.5 and appendix A): PWM outputs with the duty of the thesis' eq. 5.1, an output-compare interrupt
// once per period (the "TIM1" task), and input capture whose handler takes the count since the previous capture and
// restarts the counter (TIM_Get_Counter). Register level, no HAL; `base` is the block's address (a fake register
// file in the PC's tests). Set-up reads, modifies and writes registers shared by the channels: do it before the
// timer's interrupt is on. The handlers' functions and the safe state write single registers and never wait.

#include <cstdint>

#include "duet/cortex_m/registers.hpp"
#include "duet/stm32mp15/timer_counts.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t tim1_base = 0x4400'0000;
inline constexpr std::uintptr_t tim2_base = 0x4000'0000;
inline constexpr std::uintptr_t tim4_base = 0x4000'2000;
inline constexpr std::uintptr_t tim5_base = 0x4000'3000;

// The edges a channel captures, as its CCER polarity bits CCxNP:CCxP (RM0436, TIMx_CCER).
enum class CaptureEdges : std::uint32_t { rising = 0b0000, falling = 0b0010, both = 0b1010 };

// One input capture, taken in the channel's interrupt.
struct Capture {
  std::uint32_t count = 0;    // counter clocks from the previous take_capture to the edge
  bool captured = false;      // false: nothing was captured (or no channel 1-4), and nothing was touched
  bool overcaptured = false;  // edges were missed: `count` runs to the last of them
  bool wrapped = false;       // the counter passed 0xFFFF since the previous take: `count` is modulo 65,536
};

class Timer {
 public:
  static constexpr std::uint32_t cr1 = 0x00, dier = 0x0C, sr = 0x10, egr = 0x14, ccmr1 = 0x18, ccmr2 = 0x1C,
                                 ccer = 0x20, cnt = 0x24, psc = 0x28, arr = 0x2C, ccr1 = 0x34, bdtr = 0x44;
  static constexpr std::uint32_t counter_enable = 1U << 0U;       // CR1.CEN
  static constexpr std::uint32_t auto_reload_preload = 1U << 7U;  // CR1.ARPE
  static constexpr std::uint32_t update_flag = 1U << 0U;          // SR.UIF
  static constexpr std::uint32_t update_generation = 1U << 0U;    // EGR.UG
  static constexpr std::uint32_t idle_off_state = 1U << 10U;      // BDTR.OSSI
  static constexpr std::uint32_t main_output_enable = 1U << 15U;  // BDTR.MOE
  // A channel's 8-bit field of CCMR1/CCMR2 (channels 1 and 3 in the low byte, 2 and 4 in the next).
  static constexpr std::uint32_t input_from_own_pin = 0b01;          // CCxS = 01: input, ICx from TIx
  static constexpr std::uint32_t compare_preload = 1U << 3U;         // OCxPE
  static constexpr std::uint32_t pwm_mode_1 = 0b110U << 4U;          // OCxM = 0110: active while CNT < CCRx
  static constexpr std::uint32_t capture_compare_enable = 1U << 0U;  // CCER.CCxE, per channel nibble
  // Every timer counts captures to 16 bits, TIM2 and TIM5 (32-bit counters) too: the thesis' model and the
  // simulated robot read 16-bit counts, so that the three sensors' counts mean the same.
  static constexpr std::uint32_t capture_reload = 0xFFFF;

  explicit constexpr Timer(std::uintptr_t base, bool advanced) : base_(base), advanced_(advanced) {}

  // PWM step 1 (RM0436, PWM mode): the counter stopped, the prescaler and auto-reload for `period_ns` of a
  // `clock_hz` input clock, the auto-reload preloaded. False (nothing touched) for a period the 16-bit prescaler and
  // counter cannot make. Then the channels (enable_pwm_output, enable_compare_interrupt), then start().
  [[nodiscard]] bool configure_pwm(std::uint64_t period_ns, std::uint32_t clock_hz) const {
    const TimeBase time_base = time_base_for(period_ns, clock_hz);
    if (!time_base.possible) return false;
    write(cr1, 0);
    write(psc, time_base.prescaler);
    write(arr, time_base.reload);
    write(cr1, auto_reload_preload);
    return true;
  }

  // PWM step 2: `channel` (1-4) an output in PWM mode 1 with its compare value preloaded, at `percent` duty, its
  // output enabled (active high). False (nothing touched) for another channel.
  [[nodiscard]] bool enable_pwm_output(unsigned channel, float percent) const {
    if (!valid(channel)) return false;
    set_mode(channel, pwm_mode_1 | compare_preload);  // CCxS = 00 (output) while CCxE is still off
    write(compare_register(channel), compare_value(percent));
    modify(ccer, 0, capture_compare_enable << enable_shift(channel));
    return true;
  }

  // PWM step 2 for the once-per-period interrupt: `channel` (1-4) as a frozen output compare (no pin: CCxE stays
  // off; the flag is set on the match all the same) matching at `at_percent` of the period (eq. 5.1; 100 % is above
  // ARR, which sets the flag at the overflow), its interrupt on and a stale flag cleared. False (nothing touched) for
  // another channel. After configure_pwm (it reads ARR).
  [[nodiscard]] bool enable_compare_interrupt(unsigned channel, float at_percent) const {
    if (!valid(channel)) return false;
    set_mode(channel, 0);  // CCxS = 00, OCxM = 0000 (frozen), no preload: the compare value applies at once
    write(compare_register(channel), compare_value(at_percent));
    write(sr, ~interrupt_bit(channel));
    modify(dier, 0, interrupt_bit(channel));
    return true;
  }

  // PWM step 3: the update event loads the preloaded prescaler, reload and compare values before the counter runs
  // (so the first period has its duty already) and sets UIF, which is cleared; an advanced timer's outputs need
  // MOE, with OSSI so that MOE off later drives them to their idle level (CR2.OISx = 0: low) instead of leaving
  // them floating; then the counter runs.
  void start() const {
    write(egr, update_generation);
    write(sr, 0);
    if (advanced_) write(bdtr, main_output_enable | idle_off_state);
    write(cr1, auto_reload_preload | counter_enable);
  }

  // The duty of `channel` (1-4), from the next period on (the compare value is preloaded). False (nothing touched)
  // for another channel.
  [[nodiscard]] bool set_duty(unsigned channel, float percent) const {
    if (!valid(channel)) return false;
    write(compare_register(channel), compare_value(percent));
    return true;
  }

  // In the capture/compare interrupt: whether `channel`'s flag was set, clearing it alone (rc_w0: the ones written
  // leave the other flags); false for a channel outside 1-4.
  [[nodiscard]] bool take_compare_flag(unsigned channel) const {
    if (!valid(channel) || (read(sr) & interrupt_bit(channel)) == 0) return false;
    write(sr, ~interrupt_bit(channel));
    return true;
  }

  // `channel` (1-4) captures the counter on `edges` of its own pin (TIx), with an interrupt; the counter counts at
  // `counter_hz` from a `clock_hz` input clock, to 0xFFFF, and runs. The prescaler divides by the whole number
  // nearest to clock / counter_hz; false (nothing touched) for another channel, or when that divider is beyond the
  // 16-bit prescaler or makes a counter clock more than 0.1 % off `counter_hz` (the counts are converted to time
  // with `counter_hz`; 1 MHz from 209 MHz is exact, from the DK2's 208.88 MHz PLL 0.06 % slow).
  // One capture channel per timer: take_capture restarts the counter that the channels share.
  [[nodiscard]] bool start_capture(unsigned channel, CaptureEdges edges, std::uint32_t counter_hz,
                                   std::uint32_t clock_hz) const {
    const std::uint32_t divider = clock_divider(counter_hz, clock_hz);
    if (!valid(channel) || divider == 0) return false;
    const unsigned shift = enable_shift(channel);
    write(cr1, 0);
    write(psc, divider - 1);
    write(arr, capture_reload);
    // RM0436, input capture mode: the input (no filter, every edge), the edges, then the capture enabled.
    modify(ccer, 0xFU << shift, 0);  // CCxS can be written only while CCxE is off
    set_mode(channel, input_from_own_pin);
    modify(ccer, 0xFU << shift, (static_cast<std::uint32_t>(edges) | capture_compare_enable) << shift);
    modify(dier, 0, interrupt_bit(channel));
    write(egr, update_generation);  // loads the prescaler and zeroes the counter; sets UIF, which is no wrap
    write(sr, ~(interrupt_bit(channel) | overcapture_bit(channel) | update_flag));
    write(cr1, counter_enable);
    return true;
  }

  // In the capture interrupt, as the thesis' TIM_Get_Counter: the captured count, and the counter restarted from 0
  // (as soon as possible: each count is short by the time from the previous edge to its take, the interrupt's
  // latency, under one count at 1 MHz unless a higher-priority interrupt delays it). Reading CCRx clears the capture
  // flag (RM0436, TIMx_SR.CCxIF): writing 0 to it instead would lose an edge that came after the read. The over-capture
  // and update flags are cleared. Which edge fired on both-edge capture is not in the timer: the board reads the pin's
  // level (GPIO IDR).
  [[nodiscard]] Capture take_capture(unsigned channel) const {
    if (!valid(channel) || (read(sr) & interrupt_bit(channel)) == 0) return {};
    const std::uint32_t count = read(compare_register(channel));
    write(cnt, 0);
    const std::uint32_t status = read(sr);  // after the read of CCRx: edges missed up to it
    write(sr, ~(overcapture_bit(channel) | update_flag));
    return {count, true, (status & overcapture_bit(channel)) != 0, (status & update_flag) != 0};
  }

  // For the fault handler and Linux's shutdown request: whole-register writes (no read-modify-write), no waiting,
  // the counter left running (the compare interrupt's task goes on). An advanced timer's outputs go to their idle
  // level (low) at once (MOE off); every PWM channel (an enabled output) gets a compare value of 0, loaded at once
  // by an update event rather than at the end of the period (it restarts the counter).
  void enter_safe_state() const {
    if (advanced_) write(bdtr, idle_off_state);
    const std::uint32_t enabled = read(ccer);
    for (unsigned channel = 1; channel <= 4; ++channel) {
      const bool output = ((read(mode_register(channel)) >> mode_shift(channel)) & 0b11U) == 0;  // CCxS = 00
      if (output && ((enabled >> enable_shift(channel)) & capture_compare_enable) != 0) {
        write(compare_register(channel), 0);
      }
    }
    write(egr, update_generation);
  }

  // The outputs safe, no more interrupts, the counter stopped.
  void stop() const {
    enter_safe_state();
    write(dier, 0);
    write(cr1, 0);
  }

 private:
  static constexpr bool valid(unsigned channel) { return channel >= 1 && channel <= 4; }
  static constexpr std::uint32_t mode_register(unsigned channel) { return channel <= 2 ? ccmr1 : ccmr2; }
  static constexpr unsigned mode_shift(unsigned channel) { return 8 * ((channel - 1) % 2); }
  static constexpr unsigned enable_shift(unsigned channel) { return 4 * (channel - 1); }
  static constexpr std::uint32_t compare_register(unsigned channel) { return ccr1 + 4 * (channel - 1); }
  static constexpr std::uint32_t interrupt_bit(unsigned channel) { return 1U << channel; }          // CCxIE, CCxIF
  static constexpr std::uint32_t overcapture_bit(unsigned channel) { return 1U << (8 + channel); }  // CCxOF

  // The whole number that divides `clock_hz` nearest to `counter_hz`; 0 when none of 1 to 65,536 comes within 0.1 %.
  static constexpr std::uint32_t clock_divider(std::uint32_t counter_hz, std::uint32_t clock_hz) {
    if (counter_hz == 0) return 0;
    const std::uint64_t divider = (std::uint64_t{clock_hz} + counter_hz / 2) / counter_hz;
    if (divider == 0 || divider > 0x1'0000U) return 0;
    const std::uint64_t exact_clock = divider * counter_hz;  // the input clock that would make counter_hz exactly
    const std::uint64_t miss = exact_clock > clock_hz ? exact_clock - clock_hz : clock_hz - exact_clock;
    return miss * 1000 > exact_clock ? 0 : static_cast<std::uint32_t>(divider);
  }

  // The channel's CCMR field (its byte and OCxM's fourth bit, 16 above the others) set to `field`.
  void set_mode(unsigned channel, std::uint32_t field) const {
    const unsigned shift = mode_shift(channel);
    modify(mode_register(channel), (0xFFU << shift) | (1U << (16 + shift)), field << shift);
  }

  // The thesis' eq. 5.1: (ARR + 1) * percent / 100, truncated; percent below 0 or NaN is 0, above 100 is 100.
  [[nodiscard]] std::uint32_t compare_value(float percent) const {
    const std::uint32_t period_counts = read(arr) + 1;
    if (!(percent > 0.0F)) return 0;
    if (percent >= 100.0F) return period_counts;
    return static_cast<std::uint32_t>(static_cast<float>(period_counts) * percent / 100.0F);
  }

  [[nodiscard]] std::uint32_t read(std::uint32_t offset) const { return cortex_m::register32(base_ + offset); }
  void write(std::uint32_t offset, std::uint32_t value) const { cortex_m::register32(base_ + offset) = value; }
  void modify(std::uint32_t offset, std::uint32_t clear, std::uint32_t set_bits) const {
    cortex_m::modify32(base_ + offset, clear, set_bits);
  }

  std::uintptr_t base_;
  bool advanced_;
};

}  // namespace duet::stm32mp15
