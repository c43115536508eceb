// What runs between reset and main: FPU on, .data copied, .bss zeroed, static constructors, main, halt.

#include <cstdint>

#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/cortex_m/vector_table.hpp"

// Placed by the board's linker script (cortex_m_sections.ld).
extern "C" {
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

}  // namespace

extern "C" [[noreturn]] void Reset_Handler() {
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
