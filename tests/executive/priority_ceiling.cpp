// Priority ceilings on the emulated Cortex-M4: task L (group 4) shares data with task M (group 3), so it guards the
// data with a section at their ceiling, group 3 (BASEPRI). Inside the section L pends H (group 2, above the ceiling)
// and M (group 3, more urgent than L but at the ceiling): H runs at once, inside the section; M waits until the
// section ends, and then preempts L before L finishes. The base rate (group 1) triggers L once.

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/rt/ceiling.hpp"
#include "duet/rt/executive.hpp"
#include "traced_port.hpp"

namespace {

namespace board = duet::mps2_an386;
using duet::cortex_m::set_interrupt_pending;

constexpr unsigned line_l = board::first_software_interrupt + 5;
constexpr unsigned line_h = board::first_software_interrupt + 6;
constexpr unsigned line_m = board::first_software_interrupt + 7;

duet::tests::TracedPort port;

void base_step();
void task_l();
void nothing() {}

constexpr duet::rt::Task tasks[] = {
    {.name = "base", .priority = {1, 0}, .entry = base_step},
    {.name = "L", .kind = duet::rt::TaskKind::interrupt, .interrupt = line_l, .priority = {4, 0}, .entry = task_l},
    {.name = "H", .kind = duet::rt::TaskKind::interrupt, .interrupt = line_h, .priority = {2, 0}, .entry = nothing},
    {.name = "M", .kind = duet::rt::TaskKind::interrupt, .interrupt = line_m, .priority = {3, 0}, .entry = nothing},
};
constexpr duet::rt::ModelDescription model{.name = "priority ceiling",
                                           .base_period_ns = 1'000'000,
                                           .tasks = tasks,
                                           .initialize = nothing,
                                           .terminate = nothing,
                                           .final_tick = 3};
static_assert(duet::rt::check(model) == duet::rt::TaskTableError::none);

// What L and M share, and its ceiling: M's group.
constexpr std::size_t sharing_tasks[] = {1, 3};
constexpr duet::rt::Ceiling shared_ceiling = duet::rt::ceiling(model, sharing_tasks);
static_assert(shared_ceiling == duet::rt::Ceiling{3});

duet::rt::Executive<duet::tests::TracedPort, 4> executive{model, port};

void base_step() {
  if (executive.ticks() == 1) set_interrupt_pending(line_l);
}

void task_l() {
  const auto section = executive.section(shared_ceiling);
  port.section_entered();
  set_interrupt_pending(line_h);
  set_interrupt_pending(line_m);
  port.section_left();
}

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)
extern "C" void Software5_IRQHandler() { executive.on_interrupt_task(1); }
extern "C" void Software6_IRQHandler() { executive.on_interrupt_task(2); }
extern "C" void Software7_IRQHandler() { executive.on_interrupt_task(3); }

int main() {
  board::initialize();
  duet::cortex_m::console_write(
      "ceiling 3: L (4) in a section pends H (2) and M (3); tasks 0 base, 1 L, 2 H, 3 M; [ ] the section\n");
  if (!duet::mps2_an386::run_model(executive, model)) return 1;
  port.print_trace(20);
  duet::cortex_m::console_write(executive.longest_section(shared_ceiling) > 0 ? "section measured\n"
                                                                              : "section not measured\n");
  return 0;
}
