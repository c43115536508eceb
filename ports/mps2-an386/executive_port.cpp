#include "duet/mps2_an386/executive_port.hpp"

namespace duet::mps2_an386 {
namespace {

constexpr std::uint32_t nanoseconds_per_second = 1'000'000'000;

}  // namespace

bool ExecutivePort::configure(const rt::ModelDescription& model) {
  const std::size_t rates = rt::rate_count(model);
  if (rates > max_rates) return false;
  cycle_counter.start_free_running();
  cortex_m::set_priority_grouping(model.sub_priority_bits);
  for (std::size_t index = 0; index < model.tasks.size(); ++index) {
    const rt::Task& task = model.tasks[index];
    const unsigned line = index == 0 ? timer0_interrupt : index < rates ? rate_interrupt(index) : task.interrupt;
    cortex_m::set_interrupt_priority(
        line, cortex_m::grouped_priority(task.priority.group, task.priority.sub, model.sub_priority_bits));
    cortex_m::enable_interrupt(line);
  }
  return true;
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
