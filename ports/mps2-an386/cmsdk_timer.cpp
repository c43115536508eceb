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

bool CmsdkTimer::pause() const {
  const std::uint32_t settings = register32(base_ + control);
  register32(base_ + control) = settings & ~enable;
  return (settings & enable) != 0;
}

// Paused at 0, the counter has interrupted and would reload on its next cycle; QEMU's model cannot restart from 0
// (it prints "Timer with delta zero, disabling" and stops), so it restarts from the reload value: one cycle early.
void CmsdkTimer::resume() const {
  if (register32(base_ + current_value) == 0) register32(base_ + current_value) = register32(base_ + reload);
  register32(base_ + control) = register32(base_ + control) | enable;
}

}  // namespace duet::mps2_an386
