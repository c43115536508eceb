#pragma once
// The executive's port on the STM32MP15's Cortex-M4 (see duet/rt/executive.hpp): TIM7's update interrupt at the
// base rate, the core's DWT cycle counter (209 MHz) for execution times, and in multitasking mode slower rate r on
// rate_interrupts[r], a line no hardware raises (board.hpp: spare_interrupts, handlers Software0 and Software1),
// pended from software.

#include <array>
#include <cstddef>
#include <cstdint>

#include "duet/cortex_m/cycle_counter.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/rt/task_table.hpp"
#include "duet/stm32mp15/basic_timer.hpp"
#include "duet/stm32mp15/board.hpp"

namespace duet::stm32mp15 {

class ExecutivePort {
 public:
  using CriticalSection = cortex_m::PriorityCeiling;

  // The lines of slower rates 1, 2, ...; index 0 is the base rate's, TIM7.
  static constexpr std::array<unsigned, 3> rate_interrupts{interrupt::tim7, spare_interrupts[0], spare_interrupts[1]};
  static constexpr std::size_t max_rates = rate_interrupts.size();

  // Starts TIM7's clock and the cycle counter, sets the priority grouping and every task's priority from the model's
  // table, and enables the lines of its rates and interrupt tasks. Call before Executive::run(). False, with nothing
  // enabled, if TIM7 cannot make the base period or the model has more rates than there are lines for them.
  [[nodiscard]] static bool configure(const rt::ModelDescription& model);

  [[nodiscard]] std::uint32_t cycles() const { return cortex_m::cycle_counter::now(); }
  void start_base_timer(std::uint32_t period_ns) { (void)base_timer.start(period_ns, timer_clock_hz); }
  void stop_base_timer() {
    base_timer.stop();
    skip_base_tick();
  }
  [[nodiscard]] bool base_tick_pending() const { return cortex_m::interrupt_pending(interrupt::tim7); }
  void skip_base_tick() {
    base_timer.acknowledge();
    cortex_m::clear_interrupt_pending(interrupt::tim7);
  }
  void trigger_rate(std::size_t rate) { cortex_m::set_interrupt_pending(rate_interrupts[rate]); }
  // Sleeps until the next interrupt: the board has no emulator that sleeping would confuse.
  void idle() { asm volatile("wfi"); }

  // The base timer handler's first act: TIM7 keeps its interrupt raised until its flag is cleared.
  static void acknowledge_base_tick() { base_timer.acknowledge(); }

 private:
  static constexpr BasicTimer base_timer{tim7_base};
};

}  // namespace duet::stm32mp15

// Defines the handlers that connect `executive` (an Executive<ExecutivePort, N> with static storage) to TIM7 and to
// the lines of the slower rates. Interrupt tasks' handlers are the application's: each clears its peripheral's flag
// and calls executive.on_interrupt_task(index).
#define DUET_STM32MP15_EXECUTIVE_HANDLERS(executive)                           \
  extern "C" void TIM7_IRQHandler() {                                          \
    ::duet::stm32mp15::ExecutivePort::acknowledge_base_tick();                 \
    (executive).on_base_tick();                                                \
  }                                                                            \
  extern "C" void Software0_IRQHandler() { (executive).on_rate_interrupt(1); } \
  extern "C" void Software1_IRQHandler() { (executive).on_rate_interrupt(2); }
