// Periodic rates on the emulated Cortex-M4: rates of 1, 2 and 4 base ticks over 400 ticks of 1 ms, in the tasking mode
// the build chooses (DUET_MULTITASKING). The slowest rate works for 1.5 base periods, so in multitasking mode the base
// rate must preempt it, and never miss a tick.

#include <cstdint>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/rt/executive.hpp"
#include "traced_port.hpp"

namespace {

using duet::rt::TaskingMode;
using duet::tests::TracedPort;

#if defined(DUET_MULTITASKING)
constexpr TaskingMode mode = TaskingMode::multi;
constexpr std::uint32_t slow_work_cycles = 37'500;  // 1.5 ms at 25 MHz
#else
constexpr TaskingMode mode = TaskingMode::single;
constexpr std::uint32_t slow_work_cycles = 2'500;  // 0.1 ms: single-tasking must finish within the base period
#endif

TracedPort port;

void base_step() {}
void every_2_step() {}
void every_4_step() {
  const std::uint32_t start = port.cycles();
  while (port.cycles() - start < slow_work_cycles) {
  }
}
void initialize() {}
void terminate() { duet::cortex_m::console_write("terminate ran\n"); }

constexpr duet::rt::Task tasks[] = {
    {.name = "base", .period_ticks = 1, .priority = {1, 0}, .entry = base_step},
    {.name = "every 2", .period_ticks = 2, .priority = {2, 0}, .entry = every_2_step},
    {.name = "every 4", .period_ticks = 4, .priority = {3, 0}, .entry = every_4_step},
};
constexpr duet::rt::ModelDescription model{.name = "rates",
                                           .base_period_ns = 1'000'000,
                                           .tasks = tasks,
                                           .initialize = initialize,
                                           .terminate = terminate,
                                           .tasking_mode = mode,
                                           .final_tick = 400};
static_assert(duet::rt::check(model) == duet::rt::TaskTableError::none);

duet::rt::Executive<TracedPort, 3> executive{model, port};

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)

int main() {
  duet::mps2_an386::initialize();
  duet::cortex_m::console_write(mode == TaskingMode::multi ? "multitasking" : "single-tasking");
  duet::cortex_m::console_write(": rates of 1, 2 and 4 ticks of 1 ms, 400 ticks\n");
  if (!duet::mps2_an386::run_model(executive, model)) return 1;

  port.print_trace(24);
  duet::tests::print_task(executive, 0, "base");
  duet::tests::print_task(executive, 1, "every 2");
  duet::tests::print_task(executive, 2, "every 4");
  const bool counts_exact = executive.statistics(0).activations == 400 && executive.statistics(1).activations == 200 &&
                            executive.statistics(2).activations == 100;
  const bool no_overruns =
      executive.statistics(0).overruns + executive.statistics(1).overruns + executive.statistics(2).overruns == 0;
  return counts_exact && no_overruns && executive.ticks() == 400 ? 0 : 1;
}
