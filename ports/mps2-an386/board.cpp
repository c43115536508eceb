// Board hooks for mps2-an386 under QEMU: the console is UART0 (QEMU's first -serial) unless the image moved it,
// halting exits QEMU, a fault is reported on the console and ends QEMU with exit code 128 + exception.

#include "duet/mps2_an386/board.hpp"

#include <iterator>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/cortex_m/semihosting.hpp"
#include "duet/mps2_an386/cmsdk_uart.hpp"

namespace duet::mps2_an386 {
namespace {

constexpr CmsdkUart uarts[] = {CmsdkUart{uart0_base}, CmsdkUart{uart1_base}, CmsdkUart{uart2_base},
                               CmsdkUart{uart3_base}, CmsdkUart{uart4_base}};
const CmsdkUart* console = &uarts[0];
constexpr std::uint32_t console_baud_rate = 115'200;

}  // namespace

void select_console(unsigned number) {
  if (number < std::size(uarts)) console = &uarts[number];
}

void initialize() { console->enable_transmitter(peripheral_clock_hz, console_baud_rate); }

const CmsdkUart& console_uart() { return *console; }

}  // namespace duet::mps2_an386

namespace duet::cortex_m {

void console_write(std::string_view text) { mps2_an386::console->write(text); }

void halt(int exit_code) {
  disable_interrupts();
  semihosting::exit(exit_code);
}

// The board drives no outputs of its own: a simulated plant's are the PC's, and QEMU's exit ends the link to it.
void on_fault(const Fault& fault) {
  TextBuffer<120> report;
  report.append("fatal: ");
  if (fault.stack_overflow) report.append("stack overflow, ");
  report.append(exception_name(fault.exception));
  if (fault.exception >= 16) report.append(' ').append(fault.exception - 16U);  // the interrupt's number
  report.append(" (exception ").append(fault.exception).append(')');
  report.append(", CFSR ").append_hex(register32(cfsr_address));
  report.append(", HFSR ").append_hex(register32(hfsr_address)).append('\n');
  console_write(report.view());
  halt(static_cast<int>(128U + fault.exception));
}

}  // namespace duet::cortex_m
