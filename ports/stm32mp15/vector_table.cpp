// The vector table of the STM32MP15's Cortex-M4: 150 device interrupts, none handled yet (issue #11 names them).

#include "duet/cortex_m/vector_table.hpp"

#include "duet/stm32mp15/board.hpp"

namespace {
namespace board = duet::stm32mp15;
}  // namespace

[[gnu::section(".vector_table"), gnu::used]] constinit const duet::cortex_m::VectorTable<board::device_interrupt_count>
    vector_table{duet::cortex_m::__stack_end, duet::cortex_m::system_exception_handlers,
                 duet::cortex_m::unhandled_device_interrupts<board::device_interrupt_count>()};
