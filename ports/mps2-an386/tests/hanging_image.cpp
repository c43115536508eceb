// An image that never finishes: the QEMU runner must give up on it and fail.

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/mps2_an386/board.hpp"

int main() {
  duet::mps2_an386::initialize();
  duet::cortex_m::console_write("spinning forever\n");
  for (;;) {
    asm volatile("" ::: "memory");  // a side effect, so that the compiler keeps the loop
  }
}
