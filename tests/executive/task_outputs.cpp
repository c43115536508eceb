// Per-task outputs: with LedPerTaskPort, LED i is lit exactly while task i runs. Each task looks at the LEDs from
// inside; the base rate also reads the DWT cycle counter, which QEMU does not emulate.

#include <cstdint>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/cycle_counter.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/executive_port.hpp"
#include "duet/rt/executive.hpp"

namespace {

using duet::mps2_an386::LedPerTaskPort;

LedPerTaskPort port;
std::uint32_t leds_seen_by_base = 0;
std::uint32_t leds_seen_by_slow = 0;
std::uint32_t dwt_cycles = 1;

std::uint32_t leds() { return duet::cortex_m::register32(duet::mps2_an386::leds_register) & 0xFFU; }
void base_step() {
  leds_seen_by_base |= leds();
  dwt_cycles = duet::cortex_m::cycle_counter::now();
}
void slow_step() { leds_seen_by_slow |= leds(); }
void nothing() {}

constexpr duet::rt::Task tasks[] = {
    {.name = "base", .priority = {1, 0}, .entry = base_step},
    {.name = "every 3", .period_ticks = 3, .priority = {2, 0}, .entry = slow_step},
};
constexpr duet::rt::ModelDescription model{.name = "task outputs",
                                           .base_period_ns = 1'000'000,
                                           .tasks = tasks,
                                           .initialize = nothing,
                                           .terminate = nothing,
                                           .tasking_mode = duet::rt::TaskingMode::multi,
                                           .final_tick = 9};

duet::rt::Executive<LedPerTaskPort, 2> executive{model, port};

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(executive)

int main() {
  duet::mps2_an386::initialize();
  duet::cortex_m::cycle_counter::start();
  if (!duet::mps2_an386::run_model(executive, model)) return 1;

  duet::TextBuffer<160> line;
  line.append("LEDs lit inside the base rate: ").append_hex(leds_seen_by_base, 2);
  line.append(", inside the slow rate: ").append_hex(leds_seen_by_slow, 2);
  line.append(", after the run: ").append_hex(leds(), 2).append('\n');
  line.append("DWT cycle counter under QEMU: ").append(dwt_cycles).append('\n');
  duet::cortex_m::console_write(line.view());
  return 0;
}
