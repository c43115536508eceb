// What runs between reset and main: the stack's guard on, FPU on, .data copied, .bss zeroed, static constructors,
// main, halt.

#include <cstdint>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/cortex_m/vector_table.hpp"

// Placed by the board's linker script (cortex_m_sections.ld).
extern "C" {
extern char __stack_guard_start[];
extern char __stack_limit[];
extern std::uint32_t __data_load_start[];
extern std::uint32_t __data_start[];
extern std::uint32_t __data_end[];
extern std::uint32_t __bss_start[];
extern std::uint32_t __bss_end[];
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();
}

int main();

namespace {

// Coprocessor access control: full access to CP10 and CP11, the FPU. Code compiled for the hard-float ABI faults on its
// first floating-point instruction until this is set.
void enable_fpu() {
  duet::cortex_m::register32(0xE000ED88) |= 0xFU << 20;
  duet::cortex_m::synchronize();
}

// MPU region 0 over the stack's guard (cortex_m_sections.ld): no access, not executable, so that the first push past
// the stack's limit faults (ARMv7-M B3.5). PRIVDEFENA keeps the default memory map everywhere else, for the
// privileged code that firmware is. HFNMIENA stays 0: HardFault and NMI run without the MPU, so that the fault path
// can read a frame the core stacked into the guard.
void guard_stack() {
  constexpr std::uintptr_t region_number = 0xE000ED98, region_base = 0xE000ED9C, region_attributes = 0xE000EDA0;
  constexpr std::uintptr_t control = 0xE000ED94;
  constexpr std::uint32_t execute_never = 1U << 28, region_enable = 1U, privileged_default_map = 1U << 2,
                          mpu_enable = 1U;
  const auto guard = reinterpret_cast<std::uintptr_t>(__stack_guard_start);
  const auto guard_size = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(__stack_limit) - guard);
  // A region of 2^(SIZE + 1) bytes; the linker script makes the guard a power of two, aligned to its size.
  const auto size_field = static_cast<std::uint32_t>(__builtin_ctz(guard_size) - 1);
  duet::cortex_m::register32(region_number) = 0;
  duet::cortex_m::register32(region_base) = static_cast<std::uint32_t>(guard);
  // AP 0b000: no access at any privilege.
  duet::cortex_m::register32(region_attributes) = execute_never | size_field << 1U | region_enable;
  duet::cortex_m::register32(control) = privileged_default_map | mpu_enable;
  duet::cortex_m::synchronize();
}

}  // namespace

extern "C" [[noreturn]] void Reset_Handler() {
  guard_stack();
  enable_fpu();
  for (std::uint32_t *from = __data_load_start, *to = __data_start; to < __data_end;) *to++ = *from++;
  for (std::uint32_t* word = __bss_start; word < __bss_end;) *word++ = 0;
  for (auto constructor = __init_array_start; constructor < __init_array_end; ++constructor) (*constructor)();
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpedantic"
  // ISO C++ forbids calling main, which in a hosted program the C library calls; here start-up code is that library.
  const int exit_code = main();
#pragma GCC diagnostic pop
  duet::cortex_m::halt(exit_code);
}
