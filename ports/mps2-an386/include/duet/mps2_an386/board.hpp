#pragma once
// QEMU's mps2-an386: an Arm MPS2 FPGA board image with a Cortex-M4F (Application Note 386), as QEMU 7.2 models it.
// Numbers from Application Note 386 and QEMU's model of it.

#include <cstdint>
#include <string_view>

namespace duet::mps2_an386 {

inline constexpr std::uint32_t core_clock_hz = 25'000'000;
inline constexpr std::uint32_t peripheral_clock_hz = 25'000'000;
// QEMU's NVIC for this board implements 32 device interrupts (its "num-irq" property); the enable and pending bits of
// higher lines read as zero, so nothing there can ever run.
inline constexpr unsigned device_interrupt_count = 32;

// CMSDK APB peripherals.
inline constexpr std::uintptr_t timer0_base = 0x4000'0000;
inline constexpr std::uintptr_t timer1_base = 0x4000'1000;
inline constexpr std::uintptr_t dual_timer_base = 0x4000'2000;
// The serial communication controller's CFG1 register: the board's user LEDs, bit i for LED i.
inline constexpr std::uintptr_t leds_register = 0x4002'F004;
inline constexpr std::uintptr_t uart0_base = 0x4000'4000;
inline constexpr std::uintptr_t uart1_base = 0x4000'5000;
inline constexpr std::uintptr_t uart2_base = 0x4000'6000;
inline constexpr std::uintptr_t uart3_base = 0x4000'7000;
inline constexpr std::uintptr_t uart4_base = 0x4000'9000;

// Device interrupt numbers (exception number minus 16).
inline constexpr unsigned uart0_receive_interrupt = 0;
inline constexpr unsigned uart0_transmit_interrupt = 1;
inline constexpr unsigned uart1_receive_interrupt = 2;
inline constexpr unsigned uart1_transmit_interrupt = 3;
inline constexpr unsigned uart2_receive_interrupt = 4;
inline constexpr unsigned uart2_transmit_interrupt = 5;
inline constexpr unsigned uart_overflow_interrupt = 12;  // UARTs 0-2, ORed together
inline constexpr unsigned timer0_interrupt = 8;
inline constexpr unsigned timer1_interrupt = 9;
inline constexpr unsigned dual_timer_interrupt = 10;
inline constexpr unsigned ethernet_interrupt = 13;
inline constexpr unsigned uart3_receive_interrupt = 18;
inline constexpr unsigned uart3_transmit_interrupt = 19;
inline constexpr unsigned uart4_receive_interrupt = 20;
inline constexpr unsigned uart4_transmit_interrupt = 21;

// Lines 24-31 are wired to nothing on this board: software pends them (set_interrupt_pending) to run work at an
// interrupt priority, such as the executive's slower rates. Their handlers are Software0_IRQHandler and so on.
inline constexpr unsigned first_software_interrupt = 24;
inline constexpr unsigned software_interrupt_count = 8;

// Lines wired to nothing that are not software interrupts either: the interrupts a simulated plant raises over the
// virtual-hardware link (plant_link.hpp), by the names of the hardware they stand for. One handler,
// PlantInterrupt_IRQHandler, serves them all and asks active_exception() which one it is. The names are those of the
// STM32MP15's Cortex-M4 interrupts that duet's models use; a model may use at most these nine.
struct PlantInterrupt {
  std::string_view name;
  unsigned line;
};
inline constexpr PlantInterrupt plant_interrupts[] = {{"EXTI8", 6},         {"DMA2_Stream2", 7}, {"DMA2_Stream3", 11},
                                                      {"DMA2_Stream4", 14}, {"TIM1", 15},        {"TIM2", 16},
                                                      {"TIM4", 17},         {"TIM5", 22},        {"IPCC_RX1", 23}};

// Brings up what the board hooks need (the console, UART0 unless select_console() chose another). Call first in main.
void initialize();

// Moves the console to UART `number` (0-4, QEMU's -serial options in order), for images whose UART0 carries
// something else. Call before initialize().
void select_console(unsigned number);

// The console's UART, for applications that also read from it.
class CmsdkUart;
const CmsdkUart& console_uart();

}  // namespace duet::mps2_an386
