// The vector table of mps2-an386: 32 device interrupts. Interrupts with a name here can be handled by defining a
// function of that name; the others report themselves as unhandled.

#include "duet/cortex_m/vector_table.hpp"

#include "duet/mps2_an386/board.hpp"

// Weak: an application's definition of the same name replaces it. Default_Handler reads the active exception number,
// so its report names the right interrupt.
#define DUET_WEAK_INTERRUPT_HANDLER(name) \
  extern "C" __attribute__((weak)) void name() { Default_Handler(); }

DUET_WEAK_INTERRUPT_HANDLER(UART0_RX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART0_TX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART1_RX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART1_TX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART2_RX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART2_TX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(TIMER0_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(TIMER1_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(DUALTIMER_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART3_RX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART3_TX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART4_RX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(UART4_TX_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(Software0_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(Software1_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(Software2_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(Software3_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(Software4_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(Software5_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(Software6_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(Software7_IRQHandler)
DUET_WEAK_INTERRUPT_HANDLER(PlantInterrupt_IRQHandler)

namespace {

using duet::cortex_m::VectorTable;
namespace board = duet::mps2_an386;

constexpr auto device_interrupt_handlers = [] {
  auto handlers = duet::cortex_m::unhandled_device_interrupts<board::device_interrupt_count>();
  handlers[board::uart0_receive_interrupt] = UART0_RX_IRQHandler;
  handlers[board::uart0_transmit_interrupt] = UART0_TX_IRQHandler;
  handlers[board::uart1_receive_interrupt] = UART1_RX_IRQHandler;
  handlers[board::uart1_transmit_interrupt] = UART1_TX_IRQHandler;
  handlers[board::uart2_receive_interrupt] = UART2_RX_IRQHandler;
  handlers[board::uart2_transmit_interrupt] = UART2_TX_IRQHandler;
  handlers[board::timer0_interrupt] = TIMER0_IRQHandler;
  handlers[board::timer1_interrupt] = TIMER1_IRQHandler;
  handlers[board::dual_timer_interrupt] = DUALTIMER_IRQHandler;
  handlers[board::uart3_receive_interrupt] = UART3_RX_IRQHandler;
  handlers[board::uart3_transmit_interrupt] = UART3_TX_IRQHandler;
  handlers[board::uart4_receive_interrupt] = UART4_RX_IRQHandler;
  handlers[board::uart4_transmit_interrupt] = UART4_TX_IRQHandler;
  constexpr std::array software = {Software0_IRQHandler, Software1_IRQHandler, Software2_IRQHandler,
                                   Software3_IRQHandler, Software4_IRQHandler, Software5_IRQHandler,
                                   Software6_IRQHandler, Software7_IRQHandler};
  static_assert(software.size() == board::software_interrupt_count);
  for (unsigned line = 0; line < software.size(); ++line)
    handlers[board::first_software_interrupt + line] = software[line];
  for (const board::PlantInterrupt& interrupt : board::plant_interrupts)
    handlers[interrupt.line] = PlantInterrupt_IRQHandler;
  return handlers;
}();

}  // namespace

[[gnu::section(".vector_table"), gnu::used]] constinit const VectorTable<board::device_interrupt_count> vector_table{
    duet::cortex_m::__stack_end, duet::cortex_m::system_exception_handlers, device_interrupt_handlers};
