#include "duet/mps2_an386/cmsdk_timer.hpp"

#include "duet/cortex_m/registers.hpp"

namespace duet::mps2_an386 {
namespace {

using cortex_m::register32;

// Register offsets and bits (Arm CoreLink CMSDK, APB timer).
constexpr std::uintptr_t control = 0x0;
constexpr std::uintptr_t current_value = 0x4;  // also value_offset in the header
constexpr std::uintptr_t reload = 0x8;
constexpr std::uintptr_t interrupt_clear = 0xC;
constexpr std::uint32_t enable = 1U << 0;
constexpr std::uint32_t interrupt_enable = 1U << 3;

}  // namespace

// The counter runs from the reload value down to zero and interrupts as it reloads: a period is reload + 1 cycles.
void CmsdkTimer::start_periodic_interrupt(std::uint32_t period_cycles) const {
  register32(base_ + control) = 0;
  register32(base_ + reload) = period_cycles - 1U;
  register32(base_ + current_value) = period_cycles - 1U;
  register32(base_ + interrupt_clear) = 1;
  register32(base_ + control) = enable | interrupt_enable;
}

void CmsdkTimer::start_free_running() const {
  register32(base_ + control) = 0;
  register32(base_ + reload) = 0xFFFF'FFFFU;
  register32(base_ + current_value) = 0xFFFF'FFFFU;
  register32(base_ + control) = enable;
}

void CmsdkTimer::stop() const { register32(base_ + control) = 0; }

}  // namespace duet::mps2_an386
