#pragma once
// The STM32MP15's Cortex-M4 (numbers from shared/facts/stm32mp15.md). A placeholder until its board support lands
// (issue #11): it links an image with the chip's memory layout and vector table, and nothing more.

namespace duet::stm32mp15 {

// The M4 runs at the clock that the boot loader and Linux configured: 209 MHz on the STM32MP157C-DK2.
inline constexpr unsigned core_clock_hz = 209'000'000;
inline constexpr unsigned device_interrupt_count = 150;

}  // namespace duet::stm32mp15
