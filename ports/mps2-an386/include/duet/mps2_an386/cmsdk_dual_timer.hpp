#pragma once
// The first counter of the Arm CMSDK APB dual timer (QEMU's cmsdk-apb-dualtimer): a second periodic interrupt
// source beside timer0 and timer1.

#include <cstdint>

namespace duet::mps2_an386 {

class CmsdkDualTimer {
 public:
  explicit constexpr CmsdkDualTimer(std::uintptr_t base) : base_(base) {}

  // Interrupts every `period_cycles` peripheral clock cycles (at least 1), starting one period from now.
  void start_periodic_interrupt(std::uint32_t period_cycles) const;
  void stop() const;
  // Acknowledges the interrupt; the handler must call it. Interrupt-safe.
  void clear_interrupt() const;

 private:
  std::uintptr_t base_;
};

}  // namespace duet::mps2_an386
