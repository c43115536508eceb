// Overruns on the emulated Cortex-M4: every tenth base step (ticks 5, 15, ...) works for 1.5 base periods. With
// count-and-skip the executive counts each overrun and drops the late tick; with stop (DUET_STOP_ON_OVERRUN) the first
// overrun stops the model and terminate runs.

#include <cstdint>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/rt/executive.hpp"
#include "traced_port.hpp"

namespace {

#if defined(DUET_STOP_ON_OVERRUN)
constexpr duet::rt::OverrunPolicy policy = duet::rt::OverrunPolicy::stop;
#else
constexpr duet::rt::OverrunPolicy policy = duet::rt::OverrunPolicy::count_and_skip;
#endif
constexpr std::uint32_t long_step_cycles = 37'500;  // 1.5 ms at 25 MHz

duet::tests::TracedPort port;

void base_step();
void initialize() {}
void terminate() { duet::cortex_m::console_write("terminate ran\n"); }

constexpr duet::rt::Task tasks[] = {{.name = "base", .priority = {1, 0}, .entry = base_step}};
constexpr duet::rt::ModelDescription model{.name = "overruns",
                                           .base_period_ns = 1'000'000,
                                           .tasks = tasks,
                                           .initialize = initialize,
                                           .terminate = terminate,
                                           .overrun_policy = policy,
                                           .final_tick = 50};

duet::rt::Executive<duet::tests::TracedPort, 1> executive{model, port};

void base_step() {
  if (executive.ticks() % 10 != 5) return;
  const std::uint32_t start = port.cycles();
  while (port.cycles() - start < long_step_cycles) {
  }
}

std::string_view stop_reason_name(duet::rt::StopReason reason) {
  switch (reason) {
    case duet::rt::StopReason::none: return "none";
    case duet::rt::StopReason::model: return "the model";
    case duet::rt::StopReason::external: return "external mode";
    case duet::rt::StopReason::final_tick: return "the final tick";
    case duet::rt::StopReason::overrun: return "an overrun";
  }
  return "?";
}

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)

int main() {
  duet::mps2_an386::initialize();
  duet::cortex_m::console_write(policy == duet::rt::OverrunPolicy::stop ? "stop" : "count and skip");
  duet::cortex_m::console_write(": 1.5 ms steps at ticks 5, 15, ... of a 1 ms base rate, 50 ticks\n");
  if (!duet::mps2_an386::run_model(executive, model)) return 1;

  duet::tests::print_task(executive, 0, "base");
  duet::TextBuffer<96> line;
  line.append("ticks: ").append(executive.ticks()).append(", stopped by ");
  line.append(stop_reason_name(executive.stop_reason())).append('\n');
  duet::cortex_m::console_write(line.view());
  return 0;
}
