#include "duet/mps2_an386/executive_port.hpp"

#include <array>

#include "duet/cortex_m/task_interrupts.hpp"

namespace duet::mps2_an386 {
namespace {

constexpr std::uint32_t nanoseconds_per_second = 1'000'000'000;

}  // namespace

rt::Ceiling ExecutivePort::tasks_ceiling;
bool ExecutivePort::base_tick_at_ceiling = false;

bool ExecutivePort::configure(const rt::ModelDescription& model) {
  constexpr auto rate_lines = [] {
    std::array<unsigned, max_rates> lines{};
    for (std::size_t rate = 0; rate < max_rates; ++rate) lines[rate] = rate_interrupt(rate);
    return lines;
  }();
  if (rt::rate_count(model) > max_rates) return false;
  cycle_counter.start_free_running();
  tasks_ceiling = rt::tasks_ceiling(model);
  base_tick_at_ceiling = rt::group_priority(model, 0) == tasks_ceiling.priority;
  return cortex_m::configure_task_interrupts(model, {timer0_interrupt, rate_lines});
}

void ExecutivePort::start_base_timer(std::uint32_t period_ns) {
  const auto cycles =
      static_cast<std::uint32_t>(static_cast<std::uint64_t>(period_ns) * peripheral_clock_hz / nanoseconds_per_second);
  {
    const CriticalSection masked{tasks_ceiling};
    base_time.period_cycles = cycles;
    base_time.period_microseconds = period_ns / 1000U;
    base_time.period_nanoseconds = period_ns % 1000U;
  }
  base_timer.start_periodic_interrupt(cycles);
}

void ExecutivePort::stop_base_timer() {
  base_timer.stop();
  base_timer.clear_interrupt();
  cortex_m::clear_interrupt_pending(timer0_interrupt);
}

void ExecutivePort::skip_base_tick() {
  base_timer.clear_interrupt();
  cortex_m::clear_interrupt_pending(timer0_interrupt);
  count_base_tick();  // the tick happened; the executive drops only its activations
}

void ExecutivePort::carry_nanoseconds() {
  const auto carry = [] {
    base_time.nanoseconds += base_time.period_nanoseconds;
    if (base_time.nanoseconds >= 1000U) {
      base_time.nanoseconds -= 1000U;
      ++base_time.carried_microseconds;
    }
  };
  if (base_tick_at_ceiling) {
    carry();
  } else {
    const CriticalSection masked{tasks_ceiling};  // a more urgent task may read the time in the middle
    carry();
  }
}

std::uint32_t ExecutivePort::executive_microseconds() {
  static_assert(peripheral_clock_hz % 1'000'000U == 0, "a whole number of cycles per microsecond");
  constexpr std::uint32_t cycles_per_microsecond = peripheral_clock_hz / 1'000'000U;
  constexpr std::uint32_t nanoseconds_per_cycle = 1000U / cycles_per_microsecond;
  const CriticalSection masked{tasks_ceiling};  // the tick count must not move between the reads
  if (base_time.period_cycles == 0) return 0;   // the executive has not started
  // The timer counts down from period - 1 and reloads as it interrupts. A reload between the two reads of the count
  // shows as a rise; then the tick is pending, not yet counted. Otherwise a pending tick came before the first read.
  const std::uint32_t first = base_timer.value();
  bool tick_pending = cortex_m::interrupt_pending(timer0_interrupt);
  std::uint32_t count = base_timer.value();
  if (count > first) {
    tick_pending = true;
  } else {
    count = first;
  }
  std::uint32_t cycles = base_time.period_cycles - 1U - count;
  if (tick_pending) cycles += base_time.period_cycles;
  return base_time.ticks * base_time.period_microseconds + base_time.carried_microseconds +
         cycles / cycles_per_microsecond +
         (base_time.nanoseconds + (cycles % cycles_per_microsecond) * nanoseconds_per_cycle) / 1000U;
}

}  // namespace duet::mps2_an386
