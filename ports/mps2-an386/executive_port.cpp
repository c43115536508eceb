#include "duet/mps2_an386/executive_port.hpp"

#include <array>

#include "duet/cortex_m/task_interrupts.hpp"

namespace duet::mps2_an386 {
namespace {

constexpr std::uint32_t nanoseconds_per_second = 1'000'000'000;

}  // namespace

bool ExecutivePort::configure(const rt::ModelDescription& model) {
  constexpr auto rate_lines = [] {
    std::array<unsigned, max_rates> lines{};
    for (std::size_t rate = 0; rate < max_rates; ++rate) lines[rate] = rate_interrupt(rate);
    return lines;
  }();
  if (rt::rate_count(model) > max_rates) return false;
  cycle_counter.start_free_running();
  return cortex_m::configure_task_interrupts(model, {timer0_interrupt, rate_lines});
}

void ExecutivePort::start_base_timer(std::uint32_t period_ns) {
  const auto cycles = static_cast<std::uint64_t>(period_ns) * peripheral_clock_hz / nanoseconds_per_second;
  base_timer.start_periodic_interrupt(static_cast<std::uint32_t>(cycles));
}

void ExecutivePort::stop_base_timer() {
  base_timer.stop();
  skip_base_tick();
}

void ExecutivePort::skip_base_tick() {
  base_timer.clear_interrupt();
  cortex_m::clear_interrupt_pending(timer0_interrupt);
}

}  // namespace duet::mps2_an386
