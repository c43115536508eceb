#include "duet/mps2_an386/cmsdk_dual_timer.hpp"

#include "duet/cortex_m/registers.hpp"

namespace duet::mps2_an386 {
namespace {

using cortex_m::register32;

// Register offsets and control bits of the first counter (Arm CoreLink CMSDK, APB dual-input timer).
constexpr std::uintptr_t load = 0x00;
constexpr std::uintptr_t control = 0x08;
constexpr std::uintptr_t interrupt_clear = 0x0C;
constexpr std::uint32_t size_32_bits = 1U << 1;
constexpr std::uint32_t interrupt_enable = 1U << 5;
constexpr std::uint32_t periodic_mode = 1U << 6;
constexpr std::uint32_t enable = 1U << 7;

}  // namespace

// In periodic mode the counter reloads from LOAD and interrupts on reaching zero: a period is LOAD cycles.
void CmsdkDualTimer::start_periodic_interrupt(std::uint32_t period_cycles) const {
  register32(base_ + control) = 0;
  register32(base_ + load) = period_cycles;
  register32(base_ + interrupt_clear) = 1;
  register32(base_ + control) = enable | periodic_mode | interrupt_enable | size_32_bits;
}

void CmsdkDualTimer::stop() const { register32(base_ + control) = 0; }

void CmsdkDualTimer::clear_interrupt() const { register32(base_ + interrupt_clear) = 1; }

}  // namespace duet::mps2_an386
