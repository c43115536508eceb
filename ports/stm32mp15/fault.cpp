// The STM32MP15 M4's fault handlers (NMI, HardFault, MemManage, BusFault, UsageFault): outputs to their safe state
// first, then the fault recorded for the next start, reported on the console, and the core halted with exit code
// 128 + exception number, as Default_Handler does. They replace the weak handlers of default_handler.cpp.

#include "duet/stm32mp15/fault.hpp"

#include <cstdint>
#include <optional>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"

namespace {

using duet::stm32mp15::ExceptionFrame;
using duet::stm32mp15::FaultRecord;

// In .noinit, at the end of the MCU SRAM (stm32mp15_m4.ld): neither the start-up code nor remoteproc writes it.
[[gnu::section(".noinit.fault_record")]] FaultRecord last_fault;

}  // namespace

namespace duet::stm32mp15 {

std::optional<FaultRecord> take_last_fault() { return take_fault(last_fault); }

}  // namespace duet::stm32mp15

// Reached from the entry below with the stacked frame, interrupts masked, on the main stack.
extern "C" [[noreturn, gnu::used]] void duet_stm32mp15_fault(const ExceptionFrame* frame) {
  duet::stm32mp15::enter_safe_state();
  const std::uint32_t exception = duet::cortex_m::active_exception();
  const duet::stm32mp15::FaultStatus status = duet::stm32mp15::read_fault_status();
  duet::stm32mp15::record_fault(last_fault, exception, status, frame);

  duet::TextBuffer<200> report;
  report.append("fatal: ").append(duet::cortex_m::exception_name(exception)).append(" (exception ").append(exception);
  report.append("), CFSR ").append_hex(last_fault.cfsr).append(", HFSR ").append_hex(last_fault.hfsr);
  report.append(", MMFAR ").append_hex(last_fault.mmfar).append(", BFAR ").append_hex(last_fault.bfar);
  report.append(", PC ").append_hex(last_fault.pc).append(", LR ").append_hex(last_fault.lr);
  report.append(", xPSR ").append_hex(last_fault.xpsr).append("; outputs safe, fault ").append(last_fault.count);
  report.append(" since power-on\n");
  duet::cortex_m::console_write(report.view());
  duet::cortex_m::halt(static_cast<int>(128U + exception));
}

// Masks interrupts first, so that no handler of higher priority than a configurable fault's drives an output again.
// The frame is on the stack that was in use: EXC_RETURN, in LR on entry, has bit 2 clear for the main stack and set
// for the process stack (ARMv7-M B1.5.8). Only basic asm belongs in a naked function.
extern "C" [[gnu::naked]] void duet_stm32mp15_fault_entry() {
  asm("cpsid i\n"
      "tst lr, #4\n"
      "ite eq\n"
      "mrseq r0, msp\n"
      "mrsne r0, psp\n"
      "b duet_stm32mp15_fault\n");
}

// nothrow: an alias promises what its target does, and GCC takes the naked entry for one that cannot throw.
extern "C" {
void NMI_Handler() __attribute__((alias("duet_stm32mp15_fault_entry"), nothrow));
void HardFault_Handler() __attribute__((alias("duet_stm32mp15_fault_entry"), nothrow));
void MemManage_Handler() __attribute__((alias("duet_stm32mp15_fault_entry"), nothrow));
void BusFault_Handler() __attribute__((alias("duet_stm32mp15_fault_entry"), nothrow));
void UsageFault_Handler() __attribute__((alias("duet_stm32mp15_fault_entry"), nothrow));
}
