// Exceptions nobody handles (the faults have fault.cpp): say which one on the console, with the fault status, and
// halt.

#include <cstdint>
#include <string_view>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/cortex_m/vector_table.hpp"

namespace duet::cortex_m {

std::string_view exception_name(std::uint32_t number) {
  switch (number) {
    case 2: return "NMI";
    case 3: return "HardFault";
    case 4: return "MemManage";
    case 5: return "BusFault";
    case 6: return "UsageFault";
    case 11: return "SVCall";
    case 12: return "DebugMonitor";
    case 14: return "PendSV";
    case 15: return "SysTick";
    default: return "interrupt";
  }
}

}  // namespace duet::cortex_m

// Exit code 128 + exception number, the shell's convention for "killed by signal N", so that a test sees at once
// which exception stopped the firmware.
extern "C" void Default_Handler() {
  const std::uint32_t number = duet::cortex_m::active_exception();
  duet::TextBuffer<120> report;
  report.append("fatal: unhandled exception ")
      .append(number)
      .append(" (")
      .append(duet::cortex_m::exception_name(number));
  if (number >= 16) report.append(' ').append(number - 16U);
  // Configurable and hard fault status (ARMv7-M B3.2.15, B3.2.16): which fault, and why.
  report.append("), CFSR ").append_hex(duet::cortex_m::register32(0xE000ED28));
  report.append(", HFSR ").append_hex(duet::cortex_m::register32(0xE000ED2C)).append('\n');
  duet::cortex_m::console_write(report.view());
  duet::cortex_m::halt(static_cast<int>(128U + (number < 127U ? number : 127U)));
}

extern "C" {
void SVC_Handler() __attribute__((weak, alias("Default_Handler")));
void DebugMon_Handler() __attribute__((weak, alias("Default_Handler")));
void PendSV_Handler() __attribute__((weak, alias("Default_Handler")));
void SysTick_Handler() __attribute__((weak, alias("Default_Handler")));
}
