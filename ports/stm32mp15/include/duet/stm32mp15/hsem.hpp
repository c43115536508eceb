#pragma once
// The hardware semaphores (RM0436, HSEM) that the Cortex-M4 and Linux on the Cortex-A7s take around read-modify-writes
// of registers both cores write: a GPIO port's configuration, the EXTI's routing and edges. The numbering is ST's
// (docs/BOARD.md, "Registers shared with Linux"): semaphore 0 guards every GPIO port, 1 the EXTI, the ones Linux's
// device tree gives its pin controller and its EXTI driver, and ST's M4 examples take. The M4 takes them by the
// 1-step read lock: one read of RLRx takes a free semaphore for core 2 (the M4), process 0, and returns what it holds
// then, so the take succeeded if that is the M4's lock. A write of Rx with the M4's core number and LOCK = 0 releases
// it. Register level, no HAL; `base` is the block's address (a fake register file in the PC's tests).
//
// Bounded: a take gives up after take_attempts reads, counted (failed_takes()), so that nothing ever spins on a
// semaphore Linux does not give back. Linux holds these only for the few register writes of one pin or line. The
// 1-step lock cannot tell two contexts of the M4 apart (both are core 2, process 0): a section never nests, and the
// M4's code takes a semaphore from one context at a time (duet's: at start-up, before interrupts are on).

#include <atomic>
#include <cstdint>

#include "duet/cortex_m/registers.hpp"

namespace duet::stm32mp15 {

inline constexpr std::uintptr_t hsem_base = 0x4C00'0000;

namespace semaphore {
inline constexpr unsigned gpio = 0;  // every GPIO port's configuration registers
inline constexpr unsigned exti = 1;  // the EXTI's configuration registers
}  // namespace semaphore

class Hsem {
 public:
  static constexpr std::uint32_t read_lock_offset = 0x80;  // RLRx at 0x80 + 4x; Rx at 4x
  static constexpr std::uint32_t locked = 1U << 31U;       // LOCK
  static constexpr std::uint32_t m4_core = 2U << 8U;       // COREID of CPU2, the Cortex-M4 (the A7s': 1)
  static constexpr unsigned take_attempts = 1000;          // reads of RLRx before a take gives up

  explicit constexpr Hsem(std::uintptr_t base = hsem_base) : base_(base) {}

  // True once the M4 holds `semaphore`; false, counted, after take_attempts reads found it held by another core.
  [[nodiscard]] bool take(unsigned semaphore) const {
    for (unsigned attempt = 0; attempt < take_attempts; ++attempt) {
      if (register_at(read_lock_offset + 4U * semaphore) == (locked | m4_core)) return true;
    }
    failed_takes_.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  void release(unsigned semaphore) const { register_at(4U * semaphore) = m4_core; }

  // Runs `change` (read-modify-writes of registers another core writes too) while holding `semaphore`. False, and
  // `change` not run, if the semaphore was not to be had (take()).
  template <typename Change>
  [[nodiscard]] bool holding(unsigned semaphore, Change change) const {
    if (!take(semaphore)) return false;
    change();
    release(semaphore);
    return true;
  }

  // Takes that gave up, since start-up, on every semaphore.
  [[nodiscard]] static std::uint32_t failed_takes() { return failed_takes_.load(std::memory_order_relaxed); }

 private:
  [[nodiscard]] volatile std::uint32_t& register_at(std::uint32_t offset) const {
    return cortex_m::register32(base_ + offset);
  }

  static inline std::atomic<std::uint32_t> failed_takes_{0};
  std::uintptr_t base_;
};

}  // namespace duet::stm32mp15
