// Benchmark: instructions per base tick of an empty model on the emulated Cortex-M4 (QEMU -icount shift=0), averaged
// over 10,000 ticks of 10 us. Target (issue #23): at most 80 (150 before). Exits with 1 above the target.

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"
#include "tick_overhead.hpp"

namespace {

constexpr std::uint32_t period_ns = 10'000;
constexpr std::uint32_t ticks = 10'000;
constexpr std::uint64_t target_hundredths = 80'00;

void empty_step() {}

}  // namespace

DUET_MPS2_AN386_EXECUTIVE_HANDLERS(*duet::bench::running_executive)

int main() {
  duet::mps2_an386::initialize();
  duet::cortex_m::enable_interrupts();
  const std::uint64_t hundredths = duet::bench::hundredths_of_instructions_per_tick(period_ns, ticks, empty_step);
  duet::TextBuffer<128> line;
  line.append("empty model: ").append(hundredths / 100U).append('.');
  line.append(hundredths % 100U < 10U ? "0" : "").append(hundredths % 100U);
  line.append(" instructions per base tick (").append(ticks).append(" ticks of 10 us, target <= 80)\n");
  duet::cortex_m::console_write(line.view());
  return hundredths != 0 && hundredths <= target_hundredths ? 0 : 1;
}
