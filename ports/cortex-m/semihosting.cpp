#include "duet/cortex_m/semihosting.hpp"

#include <cstdint>

namespace duet::cortex_m::semihosting {
namespace {

// Semihosting operations and reasons, from ARM's "Semihosting for AArch32 and AArch64" specification.
constexpr std::uint32_t sys_exit_extended = 0x20;
constexpr std::uint32_t application_exit = 0x20026;

std::uint32_t call(std::uint32_t operation, const void* parameters) {
  register std::uint32_t r0 asm("r0") = operation;
  register const void* r1 asm("r1") = parameters;
  asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

}  // namespace

void exit(int exit_code) {
  const std::uint32_t parameters[2] = {application_exit, static_cast<std::uint32_t>(exit_code)};
  call(sys_exit_extended, parameters);
  for (;;) {  // not reached under an emulator; a debugger may resume, and then there is nothing left to run
    asm volatile("wfi");
  }
}

}  // namespace duet::cortex_m::semihosting
