// Board hooks for the STM32MP15's Cortex-M4. The console is the remoteproc trace buffer (resource_table.hpp):
// Linux shows its text in /sys/kernel/debug/remoteproc/remoteproc0/trace0, up to the first NUL, so the text is
// kept NUL-terminated and, when the buffer is full, starts again at its beginning. Halting parks the core until
// Linux's remoteproc stops or restarts it.

#include <cstddef>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/stm32mp15/resource_table.hpp"

namespace duet::cortex_m {
namespace {

std::size_t trace_end = 0;  // where the next character goes

}  // namespace

void console_write(std::string_view text) {
  const InterruptMask masked;  // any priority may log
  for (const char character : text) {
    if (trace_end + 1 >= stm32mp15::trace_buffer_size) trace_end = 0;
    stm32mp15::trace_buffer[trace_end++] = character;
  }
  stm32mp15::trace_buffer[trace_end] = '\0';
}

void halt(int /*exit_code*/) {
  disable_interrupts();
  for (;;) {
    asm volatile("wfi");
  }
}

}  // namespace duet::cortex_m
