// The mps2-an386 self-test: checks that start-up, the console, the FPU, a timer interrupt and the exit code work.
// ctest boots it in QEMU and compares its console output with expected_output.txt.

#include <cstdint>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/systick.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/cmsdk_timer.hpp"
#include "duet/version.hpp"

namespace {

namespace board = duet::mps2_an386;
namespace cortex_m = duet::cortex_m;

constexpr board::CmsdkTimer timer{board::timer0_base};
constexpr std::uint32_t timer_rate_hz = 1000;
constexpr std::uint32_t ticks_to_count = 100;

volatile std::uint32_t timer_ticks = 0;

// Start-up must copy initialised data, zero the rest and run constructors before main.
std::uint32_t initialised_word = 0xC0FFEE;
std::uint32_t zeroed_word;
struct ConstructedAtStartUp {
  ConstructedAtStartUp() : value(42) {}
  std::uint32_t value;
} constructed_at_start_up;

bool check(bool passed, std::string_view what) {
  duet::TextBuffer<96> line;
  line.append(passed ? "ok: " : "FAILED: ").append(what).append('\n');
  cortex_m::console_write(line.view());
  return passed;
}

// Under the hard-float ABI this faults unless start-up enabled the FPU.
bool fpu_works() {
  volatile float side = 1.5F;
  const float area = side * side;
  return static_cast<std::uint32_t>(area * 100.0F) == 225;
}

// Counts timer interrupts and measures the time they took with SysTick, which runs from the core clock.
bool timer_interrupts_arrive_at_their_rate() {
  cortex_m::set_interrupt_priority(board::timer0_interrupt, 2);
  cortex_m::enable_interrupt(board::timer0_interrupt);
  cortex_m::systick::start_free_running();
  const std::uint32_t start = cortex_m::systick::now();
  timer.start_periodic_interrupt(board::peripheral_clock_hz / timer_rate_hz);
  cortex_m::enable_interrupts();
  // Spin rather than sleep: QEMU's deterministic -icount mode merges timer interrupts while the core sleeps.
  constexpr std::uint32_t patience = 10'000'000;
  for (std::uint32_t attempt = 0; timer_ticks < ticks_to_count && attempt < patience; ++attempt) {
  }
  const std::uint32_t cycles = cortex_m::systick::cycles_since(start);
  timer.stop();
  const std::uint32_t milliseconds = (cycles + board::core_clock_hz / 2000) / (board::core_clock_hz / 1000);

  duet::TextBuffer<96> line;
  line.append("timer0 at ").append(timer_rate_hz).append(" Hz: ").append(timer_ticks);
  line.append(" interrupts in ").append(milliseconds).append(" ms\n");
  cortex_m::console_write(line.view());
  return timer_ticks >= ticks_to_count && milliseconds == ticks_to_count * 1000 / timer_rate_hz;
}

}  // namespace

extern "C" void TIMER0_IRQHandler() {
  timer.clear_interrupt();
  timer_ticks = timer_ticks + 1;
}

int main() {
  board::initialize();
  duet::TextBuffer<96> banner;
  banner.append("duet ").append(duet::version).append(" self-test on mps2-an386\n");
  cortex_m::console_write(banner.view());

  bool passed = true;
  passed &= check(initialised_word == 0xC0FFEE && zeroed_word == 0, "start-up initialised .data and .bss");
  passed &= check(constructed_at_start_up.value == 42, "start-up ran static constructors");
  passed &= check(fpu_works(), "the FPU computes 1.5 * 1.5 = 2.25");
  passed &= check(timer_interrupts_arrive_at_their_rate(), "timer0 interrupts arrive at their rate");

  cortex_m::console_write(passed ? "self-test passed\n" : "self-test FAILED\n");
  return passed ? 0 : 1;
}
