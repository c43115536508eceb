#pragma once
// Interrupt control of the Cortex-M core and its NVIC (ARMv7-M Architecture Reference Manual, B3.4).

#include <cstdint>
#include <string_view>

#include "duet/cortex_m/registers.hpp"
#include "duet/rt/ceiling.hpp"

namespace duet::cortex_m {

// Priorities are 0 (most urgent) to 15. The STM32MP15 implements 4 priority bits and QEMU's mps2-an386 8, so duet
// only ever writes the top nibble: the same firmware orders its interrupts the same way on both.
inline constexpr unsigned priority_bits = 4;
inline constexpr unsigned priority_levels = 1U << priority_bits;

// Device interrupt numbers start at 0 for exception 16; the NVIC holds at most 496.
inline constexpr unsigned max_interrupt_count = 496;

// `priority` must be below priority_levels; a larger value is taken as the least urgent level rather than wrapping
// round to a more urgent one. All are interrupt-safe: each is a single store or read-modify-write of a byte the caller
// owns.
void enable_interrupt(unsigned interrupt_number);
void disable_interrupt(unsigned interrupt_number);
void set_interrupt_pending(unsigned interrupt_number);
void clear_interrupt_pending(unsigned interrupt_number);
[[nodiscard]] inline bool interrupt_pending(unsigned interrupt_number) {  // inline: the executive asks on every tick
  constexpr std::uintptr_t set_pending_bank = 0xE000E200;
  return (register32(set_pending_bank + 4U * (interrupt_number / 32U)) & (1U << (interrupt_number % 32U))) != 0;
}
void set_interrupt_priority(unsigned interrupt_number, unsigned priority);

// Splits the 4 priority bits into a group (preemption) priority and a sub-priority of `sub_priority_bits` (0-3) bits:
// only a more urgent group preempts; among pending interrupts of one group the sub-priority, then the lower number,
// decides which runs first. Call before enabling interrupts.
void set_priority_grouping(unsigned sub_priority_bits);

// The priority value of `group` and `sub` under the grouping set_priority_grouping(sub_priority_bits) chose.
constexpr unsigned grouped_priority(unsigned group, unsigned sub, unsigned sub_priority_bits) {
  return (group << sub_priority_bits) | (sub & ((1U << sub_priority_bits) - 1U));
}

inline void enable_interrupts() { asm volatile("cpsie i" ::: "memory"); }
inline void disable_interrupts() { asm volatile("cpsid i" ::: "memory"); }

// Masks every interrupt and returns the mask as it was, for restore_interrupts(): nests, and works in handlers. As
// plain functions they also serve as a lock that libraries take by function pointer (the XCP transmit queue's).
inline std::uint32_t mask_interrupts() {
  std::uint32_t saved_primask;
  asm volatile("mrs %0, primask\n cpsid i" : "=r"(saved_primask)::"memory");
  return saved_primask;
}
inline void restore_interrupts(std::uint32_t saved_primask) {
  asm volatile("msr primask, %0" ::"r"(saved_primask) : "memory");
}

// mask_interrupts() for as long as it exists. Keep what it guards short; it delays every interrupt. Only for what is
// shared with every handler (start-up, the fault path, the console that any priority may write); what tasks share
// takes a PriorityCeiling instead.
class InterruptMask {
 public:
  InterruptMask() : saved_primask_(mask_interrupts()) {}
  ~InterruptMask() { restore_interrupts(saved_primask_); }
  InterruptMask(const InterruptMask&) = delete;
  InterruptMask& operator=(const InterruptMask&) = delete;

 private:
  std::uint32_t saved_primask_ = 0;
};

// A critical section at a priority ceiling (Stack Resource Policy, as RTIC does): masks the interrupts of priority
// `ceiling` (0-15, the NVIC value of a group with its sub-priority bits zero) and every less urgent one, and leaves
// the more urgent groups free to preempt. BASEPRI compares group priorities only, so the grouping needs no care here.
// BASEPRI_MAX raises the mask and never lowers it, so sections nest; the destructor puts back the mask it found.
// BASEPRI 0 masks nothing, so a ceiling of 0 (a resource that a task of group 0 uses) can only be had with PRIMASK,
// which then delays every interrupt, as InterruptMask does.
class PriorityCeiling {
 public:
  explicit PriorityCeiling(unsigned ceiling) : ceiling_(ceiling) {
    if (ceiling_ == 0) {
      saved_ = mask_interrupts();
    } else {
      asm volatile("mrs %0, basepri\n msr basepri_max, %1"
                   : "=&r"(saved_)
                   : "r"(ceiling_ << (8U - priority_bits))
                   : "memory");
    }
  }
  ~PriorityCeiling() {
    if (ceiling_ == 0) {
      restore_interrupts(saved_);
    } else {
      asm volatile("msr basepri, %0" ::"r"(saved_) : "memory");
    }
  }
  // The executive's ceilings (duet/rt/ceiling.hpp): this is every Cortex-M port's CriticalSection.
  explicit PriorityCeiling(rt::Ceiling ceiling) : PriorityCeiling(unsigned{ceiling.priority}) {}
  PriorityCeiling(const PriorityCeiling&) = delete;
  PriorityCeiling& operator=(const PriorityCeiling&) = delete;

 private:
  unsigned ceiling_;
  std::uint32_t saved_ = 0;
};

// The name of system exception `number` ("HardFault"), or "interrupt" for a device interrupt (16 and above).
std::string_view exception_name(std::uint32_t number);

// The exception being handled: 0 in thread mode, 1-15 for system exceptions, 16 + n for device interrupt n.
inline std::uint32_t active_exception() {
  std::uint32_t number;
  asm volatile("mrs %0, ipsr" : "=r"(number));
  return number & 0x1FFU;
}

}  // namespace duet::cortex_m
