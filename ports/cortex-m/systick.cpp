#include "duet/cortex_m/systick.hpp"

#include "duet/cortex_m/registers.hpp"

namespace duet::cortex_m::systick {
namespace {

constexpr std::uintptr_t control_and_status = 0xE000E010;
constexpr std::uintptr_t reload_value = 0xE000E014;
constexpr std::uintptr_t current_value = 0xE000E018;
constexpr std::uint32_t enable = 1U << 0;
constexpr std::uint32_t core_clock_source = 1U << 2;

}  // namespace

void start_free_running() {
  register32(control_and_status) = 0;
  register32(reload_value) = counter_mask;
  register32(current_value) = 0;  // any write clears the counter; it reloads on the next clock
  register32(control_and_status) = enable | core_clock_source;
}

std::uint32_t now() { return register32(current_value); }

}  // namespace duet::cortex_m::systick
