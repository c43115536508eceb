#include "duet/stm32mp15/executive_port.hpp"

#include "duet/cortex_m/task_interrupts.hpp"
#include "duet/stm32mp15/rcc.hpp"
#include "duet/stm32mp15/timer_counts.hpp"

namespace duet::stm32mp15 {

bool ExecutivePort::configure(const rt::ModelDescription& model) {
  if (!time_base_for(model.base_period_ns, timer_clock_hz).possible || rt::rate_count(model) > max_rates) return false;
  Rcc{}.enable(clock::tim7);
  cortex_m::cycle_counter::start();
  return cortex_m::configure_task_interrupts(model, {interrupt::tim7, rate_interrupts});
}

}  // namespace duet::stm32mp15
