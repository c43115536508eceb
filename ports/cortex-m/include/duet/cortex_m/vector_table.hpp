#pragma once
// The Cortex-M vector table: the initial stack pointer, 15 system exceptions, then the board's device interrupts.
// The core reads it at reset from address 0 (VTOR's reset value), so the board's linker script puts it there.

#include <array>
#include <cstddef>

namespace duet::cortex_m {

using ExceptionHandler = void (*)();

template <std::size_t DeviceInterruptCount>
struct VectorTable {
  const void* initial_stack_pointer;
  std::array<ExceptionHandler, 15> system_exceptions;  // exceptions 1 (reset) to 15 (SysTick)
  std::array<ExceptionHandler, DeviceInterruptCount> device_interrupts;
};

}  // namespace duet::cortex_m

// Handlers the core calls by these names. Each is weak: an application overrides one by defining it. The faults (NMI,
// HardFault, MemManage, BusFault, UsageFault) and every exception or interrupt nobody handles (Default_Handler) take
// the fault path (fault.hpp) to the board's on_fault.
extern "C" {
[[noreturn]] void Reset_Handler();
void NMI_Handler();
void HardFault_Handler();
void MemManage_Handler();
void BusFault_Handler();
void UsageFault_Handler();
void SVC_Handler();
void DebugMon_Handler();
void PendSV_Handler();
void SysTick_Handler();
void Default_Handler();
}

namespace duet::cortex_m {

inline constexpr std::array<ExceptionHandler, 15> system_exception_handlers{
    Reset_Handler,      NMI_Handler,      HardFault_Handler, MemManage_Handler, BusFault_Handler,
    UsageFault_Handler, nullptr,          nullptr,           nullptr,           nullptr,
    SVC_Handler,        DebugMon_Handler, nullptr,           PendSV_Handler,    SysTick_Handler};

// A board's device interrupt handlers before it names any: every one reports itself as unhandled.
template <std::size_t DeviceInterruptCount>
constexpr std::array<ExceptionHandler, DeviceInterruptCount> unhandled_device_interrupts() {
  std::array<ExceptionHandler, DeviceInterruptCount> handlers{};
  handlers.fill(Default_Handler);
  return handlers;
}

// The top of the stack, placed by the board's linker script.
extern "C" char __stack_end[];

}  // namespace duet::cortex_m
