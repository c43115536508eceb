// An image whose stack overflows on purpose: a recursion far deeper than the stack, with floating-point state live,
// so that the fault stacks the extended frame. The guard must stop it at once and the fault path report it.

#include <cstdint>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"

namespace {

// Each level keeps 64 bytes and a float on the stack; the caller asks for more levels than the stack holds.
[[gnu::noinline]] float descend(std::uint32_t levels, float weight) {
  volatile float frame[16];
  frame[levels % 16] = weight;
  if (levels == 0) return frame[0];
  return descend(levels - 1, weight * 0.5F) + frame[levels % 16];
}

volatile std::uint32_t levels = 100'000;  // volatile: the compiler cannot bound the recursion

}  // namespace

int main() {
  duet::mps2_an386::initialize();
  duet::cortex_m::console_write("descending until the stack overflows\n");
  const float sum = descend(levels, 1.0F);
  duet::cortex_m::console_write(sum > 0.0F ? "still running after the overflow\n" : "no overflow, sum not positive\n");
  return 0;
}
