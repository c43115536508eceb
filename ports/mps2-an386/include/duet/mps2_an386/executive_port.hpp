#pragma once
// The executive's port on mps2-an386 (see duet/rt/executive.hpp): timer0 interrupts at the base rate, timer1 runs
// free as the cycle counter (25 MHz, the core clock), and in multitasking mode the slower rate r runs from the
// software interrupt line first_software_interrupt + r.

#include <cstddef>
#include <cstdint>

#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_timer.hpp"
#include "duet/rt/task_table.hpp"

namespace duet::mps2_an386 {

class ExecutivePort {
 public:
  using CriticalSection = cortex_m::PriorityCeiling;

  // The interrupt line that runs slower rate `rate` (1 or more) in multitasking mode.
  static constexpr unsigned rate_interrupt(std::size_t rate) {
    return first_software_interrupt + static_cast<unsigned>(rate);
  }
  // Rates 1-4 use software interrupts 1-4; 0 and 5-7 are the application's.
  static constexpr std::size_t max_rates = 5;

  // Starts the cycle counter, sets the priority grouping and the priority of every task's interrupt from the model's
  // table, keeps the ceiling of its tasks for the port's own sections, and enables the interrupts of its rates and
  // interrupt tasks. Call before Executive::run(). False, with
  // nothing enabled, if the model has more rates than there are software interrupts for them.
  [[nodiscard]] static bool configure(const rt::ModelDescription& model);

  [[nodiscard]] static std::uint32_t cycles() { return ~cycle_counter.value(); }  // it counts down
  void start_base_timer(std::uint32_t period_ns);
  void stop_base_timer();
  [[nodiscard]] bool base_tick_pending() const { return cortex_m::interrupt_pending(timer0_interrupt); }
  void skip_base_tick();
  void trigger_rate(std::size_t rate) { cortex_m::set_interrupt_pending(rate_interrupt(rate)); }
  // Spins: under QEMU's -icount, sleeping in WFI merges timer interrupts.
  void idle() {}

  // The base timer handler's first act: the timer keeps its interrupt raised until it is acknowledged.
  static void acknowledge_base_tick() {
    base_timer.clear_interrupt();
    count_base_tick();
  }

  // The executive's time in microseconds (wrapping as a 32-bit count does, every 72 minutes): the base ticks so far
  // times the period, plus how far the base timer has counted into the current one. DAQ stamps samples with it, so a
  // periodic task's timestamps advance by exactly its period. Not the cycle count that an image with a plant link
  // gives the executive, which leaves out the link's cycles (plant_link.hpp). From the model's tasks or anything less
  // urgent than the most urgent of them (the ceiling of the time's words).
  [[nodiscard]] static std::uint32_t executive_microseconds();

 private:
  // What the executive's time is computed from: the base ticks so far and the period.
  struct BaseTime {
    std::uint32_t period_cycles = 0;
    std::uint32_t period_microseconds = 0;
    std::uint32_t period_nanoseconds = 0;  // beyond the whole microseconds
    std::uint32_t ticks = 0;               // wrapping, as the time in microseconds does
    // A period with nanoseconds beyond its whole microseconds adds them up at each tick: the whole microseconds they
    // made so far, and what is left (below 1000).
    std::uint32_t carried_microseconds = 0;
    std::uint32_t nanoseconds = 0;
  };
  static BaseTime base_time;

  // In the base tick, on every tick: inline, one word written (a more urgent reader sees the count before or after).
  static void count_base_tick() {
    base_time.ticks = base_time.ticks + 1U;
    if (base_time.period_nanoseconds != 0) carry_nanoseconds();
  }
  static void carry_nanoseconds();

  static constexpr CmsdkTimer base_timer{timer0_base};
  static constexpr CmsdkTimer cycle_counter{timer1_base};

 protected:
  // The ceiling of the model's tasks (configure()), and whether the base rate is at it: then the base tick, which
  // writes the time, can be preempted by none of its readers and needs no section.
  static rt::Ceiling tasks_ceiling;
  static bool base_tick_at_ceiling;
};

inline ExecutivePort::BaseTime ExecutivePort::base_time{};

// The board's executive port plus an output per task: LED i (leds_register) is lit while task i runs, for i < 8; on
// hardware the same hooks drive a pin that an oscilloscope watches.
class LedPerTaskPort : public ExecutivePort {
 public:
  static constexpr std::size_t led_count = 8;

  void task_started(std::size_t task) { set(task, true); }
  void task_finished(std::size_t task) { set(task, false); }

 private:
  static void set(std::size_t task, bool lit) {
    if (task >= led_count) return;
    const CriticalSection masked{tasks_ceiling};  // a read-modify-write that every task does
    const std::uint32_t bit = 1U << task;
    volatile std::uint32_t& register_ = cortex_m::register32(leds_register);
    register_ = lit ? (register_ | bit) : (register_ & ~bit);
  }
};

// What a board's main does with a model: configures the interrupts of its tasks, initializes it, enables interrupts,
// runs it until it stops and terminates it. False, with nothing run, if the model does not fit the board or its task
// table is wrong.
template <typename Executive>
[[nodiscard]] bool run_model(Executive& executive, const rt::ModelDescription& model) {
  if (!ExecutivePort::configure(model) || executive.initialize() != rt::TaskTableError::none) return false;
  cortex_m::enable_interrupts();
  executive.run();
  executive.terminate();
  return true;
}

}  // namespace duet::mps2_an386

// Defines the interrupt handlers that connect `executive` (an Executive<ExecutivePort, N> with static storage) to the
// base timer and to the software interrupts of the slower rates (Software1 to Software4). Interrupt tasks' handlers are
// the application's: each calls executive.on_interrupt_task(index).
#define DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)                          \
  extern "C" void TIMER0_IRQHandler() {                                        \
    ::duet::mps2_an386::ExecutivePort::acknowledge_base_tick();                \
    (executive).on_base_tick();                                                \
  }                                                                            \
  extern "C" void Software1_IRQHandler() { (executive).on_rate_interrupt(1); } \
  extern "C" void Software2_IRQHandler() { (executive).on_rate_interrupt(2); } \
  extern "C" void Software3_IRQHandler() { (executive).on_rate_interrupt(3); } \
  extern "C" void Software4_IRQHandler() { (executive).on_rate_interrupt(4); }
