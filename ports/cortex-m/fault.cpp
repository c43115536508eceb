// The fault handlers' entry (fault.hpp): off the stack that may have overflowed first, then the board's reaction.
// An interrupt nobody handles takes the same path: it is as fatal as a fault.

#include "duet/cortex_m/fault.hpp"

#include <cstdint>
#include <string_view>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/registers.hpp"

// Placed by cortex_m_sections.ld.
extern "C" {
extern char __stack_guard_start[];
extern char __stack_limit[];
}

namespace {

constexpr std::uint32_t uses_process_stack = 1U << 2;  // EXC_RETURN bit 2 (ARMv7-M B1.5.8)
constexpr std::uint32_t mmfar_valid = 1U << 7;         // CFSR.MMARVALID

// The MPU off: the fault path may read the frame the core stacked into the guard, and the board's reaction must not
// fault again on it.
void disable_mpu() {
  duet::cortex_m::register32(0xE000ED94) = 0;
  duet::cortex_m::synchronize();
}

bool in_guard(std::uintptr_t address) {
  return address >= reinterpret_cast<std::uintptr_t>(__stack_guard_start) &&
         address < reinterpret_cast<std::uintptr_t>(__stack_limit);
}

}  // namespace

namespace duet::cortex_m {

std::string_view exception_name(std::uint32_t number) {
  switch (number) {
    case 2: return "NMI";
    case 3: return "HardFault";
    case 4: return "MemManage";
    case 5: return "BusFault";
    case 6: return "UsageFault";
    case 11: return "SVCall";
    case 12: return "DebugMonitor";
    case 14: return "PendSV";
    case 15: return "SysTick";
    default: return "interrupt";
  }
}

}  // namespace duet::cortex_m

// Reached from the entry below on the fault stack, interrupts masked, with the stacked frame's address and EXC_RETURN.
extern "C" [[noreturn, gnu::used]] void duet_cortex_m_fault(std::uintptr_t frame, std::uint32_t exception_return) {
  disable_mpu();
  const std::uint32_t cfsr = duet::cortex_m::register32(duet::cortex_m::cfsr_address);
  const bool main_stack = (exception_return & uses_process_stack) == 0;
  const bool access_in_guard =
      (cfsr & mmfar_valid) != 0 && in_guard(duet::cortex_m::register32(duet::cortex_m::mmfar_address));
  const bool overflow = (main_stack && frame < reinterpret_cast<std::uintptr_t>(__stack_limit)) || access_in_guard;
  duet::cortex_m::on_fault({duet::cortex_m::active_exception(), frame, overflow});
}

// Masks interrupts first, so that no handler of higher priority than a configurable fault's drives an output again,
// then moves the main stack pointer to the top of the fault stack before anything is pushed. The frame is on the
// stack that was in use: EXC_RETURN, in LR on entry, has bit 2 clear for the main stack, set for the process stack.
// Only basic asm belongs in a naked function.
extern "C" [[gnu::naked]] void duet_cortex_m_fault_entry() {
  asm("cpsid i\n"
      "tst lr, #4\n"
      "ite eq\n"
      "mrseq r0, msp\n"
      "mrsne r0, psp\n"
      "mov r1, lr\n"
      "movw r2, #:lower16:__fault_stack_end\n"
      "movt r2, #:upper16:__fault_stack_end\n"
      "mov sp, r2\n"
      "b duet_cortex_m_fault\n");
}

// Weak: a board or an application may replace one. nothrow: an alias promises what its target does, and GCC takes
// the naked entry for one that cannot throw.
extern "C" {
void Default_Handler() __attribute__((alias("duet_cortex_m_fault_entry"), nothrow));
void NMI_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
void HardFault_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
void MemManage_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
void BusFault_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
void UsageFault_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
void SVC_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
void DebugMon_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
void PendSV_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
void SysTick_Handler() __attribute__((weak, alias("duet_cortex_m_fault_entry"), nothrow));
}
