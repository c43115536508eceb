// The thesis' step-time test on the emulated Cortex-M4: a model whose only work is to toggle an output every base
// step (a square wave on the board's LED0), run at shorter and shorter base periods. A period is met when no step
// overran and every toggle came one period, within one timer cycle (40 ns), after the one before. Run under -icount
// shift=2: 4 ns per instruction, about the STM32MP15's Cortex-M4 at 209 MHz and one instruction per cycle. Exits with
// 1 unless every period down to 10 us is met (the target of issue #3).

#include <array>
#include <cstdint>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_timer.hpp"
#include "duet/rt/executive.hpp"
#include "tick_overhead.hpp"

namespace {

namespace board = duet::mps2_an386;
using duet::bench::CountingExecutive;
using duet::bench::CountingPort;

constexpr unsigned icount_shift = 2;

struct Period {
  std::uint32_t ns;
  std::uint32_t steps;
  std::string_view name;
};
constexpr std::array periods = {
    Period{1'000'000'000, 2, "1 s"}, Period{100'000'000, 10, "100 ms"}, Period{10'000'000, 100, "10 ms"},
    Period{1'000'000, 1000, "1 ms"}, Period{100'000, 1000, "100 us"},   Period{20'000, 1000, "20 us"},
    Period{10'000, 1000, "10 us"},   Period{5'000, 1000, "5 us"},       Period{2'000, 1000, "2 us"},
    Period{1'000, 1000, "1 us"},     Period{500, 1000, "500 ns"},
};

// What the step records of the square wave: when it toggled, and the shortest and longest time between toggles.
struct Wave {
  std::uint32_t toggles = 0;
  std::uint32_t last_cycles = 0;
  std::uint32_t shortest = UINT32_MAX;
  std::uint32_t longest = 0;
};
Wave wave;
constexpr board::CmsdkTimer cycle_counter{board::timer1_base};  // runs free once the executive port is configured

void toggle_output() {
  volatile std::uint32_t& leds = duet::cortex_m::register32(board::leds_register);
  leds = leds ^ 1U;  // LED0
  const std::uint32_t now = ~cycle_counter.value();
  if (wave.toggles++ != 0) {
    const std::uint32_t interval = now - wave.last_cycles;
    if (interval < wave.shortest) wave.shortest = interval;
    if (interval > wave.longest) wave.longest = interval;
  }
  wave.last_cycles = now;
}
void nothing() {}

constexpr duet::rt::Task tasks[] = {{.name = "toggle", .priority = {1, 0}, .entry = toggle_output}};

// Runs the square wave at one period; true if every deadline was met.
bool run_at(const Period& period) {
  const duet::rt::ModelDescription model{.name = "step time",
                                         .base_period_ns = period.ns,
                                         .tasks = tasks,
                                         .initialize = nothing,
                                         .terminate = nothing,
                                         .final_tick = period.steps};
  CountingPort port;
  CountingExecutive executive{model, port};
  wave = {};
  duet::bench::running_executive = &executive;
  const bool ran = duet::mps2_an386::run_model(executive, model);
  duet::bench::running_executive = nullptr;
  if (!ran) return false;

  const std::uint32_t period_cycles =
      static_cast<std::uint32_t>(static_cast<std::uint64_t>(period.ns) * board::peripheral_clock_hz / 1'000'000'000U);
  const std::uint32_t overruns = executive.statistics(0).overruns;
  // QEMU takes an interrupt at the end of a block of translated instructions, so the toggle may come one timer
  // cycle (40 ns) late or early, as it would on hardware by interrupt latency.
  const bool met = overruns == 0 && wave.toggles == period.steps && wave.shortest + 1U >= period_cycles &&
                   wave.longest <= period_cycles + 1U;
  duet::TextBuffer<160> line;
  line.append("period ").append(period.name).append(": ").append(wave.toggles).append(" toggles, ");
  line.append(overruns).append(" overruns, toggle intervals ").append(wave.shortest).append("..");
  line.append(wave.longest).append(" timer cycles of ").append(period_cycles).append(": ");
  line.append(met ? "met\n" : "NOT met\n");
  duet::cortex_m::console_write(line.view());
  return met;
}

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(*duet::bench::running_executive)

int main() {
  board::initialize();
  duet::cortex_m::console_write(
      "step-time test: LED0 toggled every base step, -icount shift=2 (4 ns per instruction)\n");
  duet::cortex_m::enable_interrupts();
  // The target (issue #3): every period down to 10 us is met.
  constexpr std::uint32_t target_ns = 10'000;
  std::string_view smallest_met = "none";
  bool target_met = true;
  for (const Period& period : periods) {
    const bool met = run_at(period);
    if (met) smallest_met = period.name;
    if (!met && period.ns >= target_ns) target_met = false;
  }

  // The cost of a step, interrupt entry to exit: measured as in the empty-model benchmark.
  const std::uint64_t hundredths =
      duet::bench::hundredths_of_instructions_per_tick(100'000, 1000, toggle_output, icount_shift);
  duet::TextBuffer<160> line;
  line.append("smallest period met: ").append(smallest_met).append("; one step costs ").append(hundredths / 100U);
  line.append(" instructions = ").append(hundredths * 4U / 100U).append(" ns at 4 ns per instruction\n");
  duet::cortex_m::console_write(line.view());
  return target_met ? 0 : 1;
}
