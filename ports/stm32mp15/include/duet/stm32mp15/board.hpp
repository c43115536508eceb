#pragma once
// The STM32MP15's Cortex-M4 (numbers from shared/facts/stm32mp15.md and RM0436): its clock, and the device
// interrupt numbers duet uses (the M4's exception number is 16 + these).

namespace duet::stm32mp15 {

// The M4 runs at the clock that the boot loader and Linux configured: 209 MHz on the STM32MP157C-DK2.
inline constexpr unsigned core_clock_hz = 209'000'000;
inline constexpr unsigned device_interrupt_count = 150;

namespace interrupt {
inline constexpr unsigned exti0 = 6;  // EXTI1-4 follow: 7-10
inline constexpr unsigned adc1 = 18;
inline constexpr unsigned exti5 = 23;
inline constexpr unsigned tim1_update = 25;
inline constexpr unsigned tim1_capture_compare = 27;
inline constexpr unsigned tim2 = 28;
inline constexpr unsigned tim4 = 30;
inline constexpr unsigned exti10 = 40;
inline constexpr unsigned exti11 = 42;
inline constexpr unsigned tim5 = 50;
inline constexpr unsigned tim6 = 54;
inline constexpr unsigned tim7 = 55;
inline constexpr unsigned dma2_stream2 = 58;
inline constexpr unsigned dma2_stream3 = 59;
inline constexpr unsigned dma2_stream4 = 60;
inline constexpr unsigned exti6 = 64;
inline constexpr unsigned exti7 = 65;
inline constexpr unsigned exti8 = 66;
inline constexpr unsigned exti9 = 67;
inline constexpr unsigned exti12 = 76;
inline constexpr unsigned exti13 = 77;
inline constexpr unsigned spi5 = 85;
inline constexpr unsigned dmamux1_overrun = 102;
inline constexpr unsigned ipcc_rx1 = 103;
inline constexpr unsigned ipcc_tx1 = 104;
inline constexpr unsigned exti14 = 121;
inline constexpr unsigned hsem_it2 = 125;
inline constexpr unsigned exti15 = 127;
}  // namespace interrupt

// The device interrupt of EXTI line `line` (0-15): each line has its own.
constexpr unsigned exti_interrupt(unsigned line) {
  constexpr unsigned lines[16] = {interrupt::exti0,      interrupt::exti0 + 1, interrupt::exti0 + 2,
                                  interrupt::exti0 + 3,  interrupt::exti0 + 4, interrupt::exti5,
                                  interrupt::exti6,      interrupt::exti7,     interrupt::exti8,
                                  interrupt::exti9,      interrupt::exti10,    interrupt::exti11,
                                  interrupt::exti12,     interrupt::exti13,    interrupt::exti14,
                                  interrupt::exti15};
  return lines[line & 15U];
}

}  // namespace duet::stm32mp15
