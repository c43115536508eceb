#pragma once
// The fault path every Cortex-M board shares (fault.cpp): NMI, HardFault, MemManage, BusFault, UsageFault and any
// exception or interrupt nobody handles (Default_Handler) mask interrupts, leave the stack that was in use, which may
// be the one that just overflowed, for a fault stack of their own (cortex_m_sections.ld), turn the MPU off and hand the
// board what happened (board_hooks.hpp, on_fault).

#include <cstdint>

namespace duet::cortex_m {

struct Fault {
  std::uint32_t exception;  // 2 NMI, 3 HardFault, 4 MemManage, 5 BusFault, 6 UsageFault; 16 + n interrupt n
  // Where the core stacked the interrupted context's frame (ARMv7-M B1.5.6), on the stack that was in use. Holds
  // nothing if stacking failed (CFSR.MSTKERR or CFSR.STKERR).
  std::uintptr_t frame;
  // The main stack ran past its limit: the frame lies below it, or the faulting access was in the stack's guard.
  bool stack_overflow;
};

// The fault status registers (ARMv7-M B3.2.15-B3.2.18): which fault and why, and the faulting address when CFSR says
// it is valid.
inline constexpr std::uintptr_t cfsr_address = 0xE000'ED28, hfsr_address = 0xE000'ED2C, mmfar_address = 0xE000'ED34,
                                bfar_address = 0xE000'ED38;

}  // namespace duet::cortex_m
