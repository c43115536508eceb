// Board hooks for mps2-an386 under QEMU: the console is UART0 (QEMU's first -serial) unless the image moved it,
// halting exits QEMU.

#include "duet/mps2_an386/board.hpp"

#include <iterator>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
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

}  // namespace duet::cortex_m
