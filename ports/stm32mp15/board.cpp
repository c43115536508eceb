// Board hooks for the STM32MP15's Cortex-M4, placeholder edition: there is no console yet (the remoteproc trace
// buffer arrives with issue #11), and halting parks the core until Linux's remoteproc stops or restarts it.

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"

namespace duet::cortex_m {

void console_write(std::string_view /*text*/) {}

void halt(int /*exit_code*/) {
  disable_interrupts();
  for (;;) {
    asm volatile("wfi");
  }
}

}  // namespace duet::cortex_m
