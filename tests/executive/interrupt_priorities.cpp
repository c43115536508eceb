// Interrupt tasks on the emulated Cortex-M4, with one sub-priority bit. Task A (group 2) triggers B (group 1): B
// preempts A. Then A triggers C (group 2, sub 1) and D (group 2, sub 0): neither preempts A, since they share its
// group, and once A is done D runs before C, although C was triggered first and has the lower line number.

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/rt/executive.hpp"
#include "traced_port.hpp"

namespace {

namespace board = duet::mps2_an386;
using duet::cortex_m::set_interrupt_pending;

constexpr unsigned line_a = board::first_software_interrupt + 0;
constexpr unsigned line_b = board::first_software_interrupt + 5;
constexpr unsigned line_c = board::first_software_interrupt + 6;
constexpr unsigned line_d = board::first_software_interrupt + 7;

duet::tests::TracedPort port;

void base_step();
void task_a() {
  set_interrupt_pending(line_b);
  set_interrupt_pending(line_c);
  set_interrupt_pending(line_d);
}
void nothing() {}

constexpr duet::rt::Task tasks[] = {
    {.name = "base", .priority = {1, 0}, .entry = base_step},
    {.name = "A", .kind = duet::rt::TaskKind::interrupt, .interrupt = line_a, .priority = {2, 0}, .entry = task_a},
    {.name = "B", .kind = duet::rt::TaskKind::interrupt, .interrupt = line_b, .priority = {1, 1}, .entry = nothing},
    {.name = "C", .kind = duet::rt::TaskKind::interrupt, .interrupt = line_c, .priority = {2, 1}, .entry = nothing},
    {.name = "D", .kind = duet::rt::TaskKind::interrupt, .interrupt = line_d, .priority = {2, 0}, .entry = nothing},
};
constexpr duet::rt::ModelDescription model{.name = "interrupt priorities",
                                           .base_period_ns = 1'000'000,
                                           .tasks = tasks,
                                           .initialize = nothing,
                                           .terminate = nothing,
                                           .final_tick = 3,
                                           .sub_priority_bits = 1};
static_assert(duet::rt::check(model) == duet::rt::TaskTableError::none);

duet::rt::Executive<duet::tests::TracedPort, 5> executive{model, port};

// The base rate (group 1) triggers A once; A waits until the base step is over.
void base_step() {
  if (executive.ticks() == 1) set_interrupt_pending(line_a);
}

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)
extern "C" void Software0_IRQHandler() { executive.on_interrupt_task(1); }
extern "C" void Software5_IRQHandler() { executive.on_interrupt_task(2); }
extern "C" void Software6_IRQHandler() { executive.on_interrupt_task(3); }
extern "C" void Software7_IRQHandler() { executive.on_interrupt_task(4); }

int main() {
  board::initialize();
  duet::cortex_m::console_write(
      "interrupt tasks: A (2.0) triggers B (1.1), C (2.1), D (2.0); tasks 0 base, 1 A, 2 B, 3 C, 4 D\n");
  if (!duet::mps2_an386::run_model(executive, model)) return 1;
  port.print_trace(16);
  return 0;
}
