// The STM32MP15 M4's reaction to a fault (the board's on_fault, entered from the shared fault path of
// ports/cortex-m/fault.cpp on its own stack): outputs to their safe state first, then the fault recorded for the next
// start, reported on the console, and the core halted with exit code 128 + exception number.

#include "duet/stm32mp15/fault.hpp"

#include <cstdint>
#include <optional>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/fault.hpp"
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

namespace duet::cortex_m {

void on_fault(const Fault& fault) {
  duet::stm32mp15::enter_safe_state();
  const duet::stm32mp15::FaultStatus status = duet::stm32mp15::read_fault_status();
  duet::stm32mp15::record_fault(last_fault, fault.exception, status,
                                reinterpret_cast<const ExceptionFrame*>(fault.frame), fault.stack_overflow);

  duet::TextBuffer<200> report;
  report.append("fatal: ");
  if (fault.stack_overflow) report.append("stack overflow, ");
  report.append(exception_name(fault.exception));
  if (fault.exception >= 16) report.append(' ').append(fault.exception - 16U);  // the interrupt's number
  report.append(" (exception ").append(fault.exception);
  report.append("), CFSR ").append_hex(last_fault.cfsr).append(", HFSR ").append_hex(last_fault.hfsr);
  report.append(", MMFAR ").append_hex(last_fault.mmfar).append(", BFAR ").append_hex(last_fault.bfar);
  report.append(", PC ").append_hex(last_fault.pc).append(", LR ").append_hex(last_fault.lr);
  report.append(", xPSR ").append_hex(last_fault.xpsr).append("; outputs safe, fault ").append(last_fault.count);
  report.append(" since power-on\n");
  console_write(report.view());
  halt(static_cast<int>(128U + fault.exception));
}

}  // namespace duet::cortex_m
