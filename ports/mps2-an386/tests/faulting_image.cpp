// An image that executes an undefined instruction: the fault must reach the console and QEMU's exit code.

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"

int main() {
  duet::mps2_an386::initialize();
  duet::cortex_m::console_write("about to execute an undefined instruction\n");
  asm volatile("udf #0");
  duet::cortex_m::console_write("still running after the fault\n");
  return 0;
}
