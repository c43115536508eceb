#pragma once
// What the M4 does when it faults (issue #11: "a fault handler puts every motor output in its safe state and records
// the fault for the next start"): the board's safe outputs, which the application gives at start-up, and the fault
// record that outlives the restart. Registers at `base + offset` like the drivers, so that the PC's tests pass fake
// register files; the handlers' entry, which reads the core's registers, is fault.cpp, the M4's only.

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "duet/cortex_m/registers.hpp"
#include "duet/stm32mp15/gpio.hpp"
#include "duet/stm32mp15/timer.hpp"

namespace duet::stm32mp15 {

// A GPIO output and the level at which it is safe, e.g. a motor driver's standby pin low.
struct SafePin {
  std::uintptr_t port;  // gpio_base(n)
  unsigned pin;         // 0-15
  bool level;
};

// The board's safe state. The tables are kept, not copied: give arrays of static storage (constexpr tables).
struct SafeState {
  std::span<const SafePin> pins;
  std::span<const Timer> timers;  // their PWM outputs off (Timer::enter_safe_state)
};

namespace detail {
inline constinit SafeState safe_state{};
}  // namespace detail

// At start-up, before the outputs are first driven.
inline void set_safe_state(const SafeState& state) { detail::safe_state = state; }

// Puts every output of the safe state in its safe level: from the fault handlers and when Linux asks the M4 to shut
// down. First the pins, one BSRR store each, which act at once; then each timer's PWM outputs: MOE off at once on an
// advanced timer, every PWM channel's compare value 0 loaded by an update event. A loop over the tables only,
// accesses to their registers only: nothing that can fault again on a sane table. The caller keeps whatever would
// drive the outputs again from running (the fault handlers mask interrupts).
inline void enter_safe_state() {
  for (const SafePin& pin : detail::safe_state.pins) {
    if (pin.pin < 16) GpioPort{pin.port}.set(pin.pin, pin.level);  // a larger number names no pin of the port
  }
  for (const Timer& timer : detail::safe_state.timers) timer.enter_safe_state();
}

// The basic frame the core stacks on exception entry (ARMv7-M B1.5.6), where the stack pointer in use then points.
struct ExceptionFrame {
  std::uint32_t r0, r1, r2, r3, r12, lr, pc, xpsr;
};

// The System Control Block's fault status and address registers (ARMv7-M B3.2.15-B3.2.18). MMFAR and BFAR hold an
// address only when CFSR's MMARVALID (bit 7) or BFARVALID (bit 15) says so.
struct FaultStatus {
  static constexpr std::uintptr_t registers = 0xE000'ED28;  // CFSR; the others follow
  static constexpr std::uint32_t cfsr_offset = 0x00, hfsr_offset = 0x04, mmfar_offset = 0x0C, bfar_offset = 0x10;
  // CFSR.MSTKERR, CFSR.STKERR: stacking the frame failed, so it holds nothing (and reading it may fault again).
  static constexpr std::uint32_t stacking_errors = 1U << 4U | 1U << 12U;

  std::uint32_t cfsr, hfsr, mmfar, bfar;
};

inline FaultStatus read_fault_status(std::uintptr_t base = FaultStatus::registers) {
  return {cortex_m::register32(base + FaultStatus::cfsr_offset), cortex_m::register32(base + FaultStatus::hfsr_offset),
          cortex_m::register32(base + FaultStatus::mmfar_offset),
          cortex_m::register32(base + FaultStatus::bfar_offset)};
}

// What the next start learns of the last fault. Kept in memory that neither the start-up code nor Linux's remoteproc
// writes (.noinit, stm32mp15_m4.ld), whose contents after power-on are garbage: `magic` tells a record from that.
// Change the magic values when the layout changes, so that an image never reads another's record.
struct FaultRecord {
  static constexpr std::uint32_t unreported = 0x6661'756D;  // a fault the next start has not taken yet
  static constexpr std::uint32_t reported = ~unreported;    // taken; `count` still counts

  std::uint32_t magic;
  std::uint32_t count;      // faults since power-on, or since the record was last garbage
  std::uint32_t exception;  // 2 NMI, 3 HardFault, 4 MemManage, 5 BusFault, 6 UsageFault
  std::uint32_t cfsr, hfsr, mmfar, bfar;
  std::uint32_t pc, lr, xpsr;    // as stacked; 0 when stacking failed
  std::uint32_t stack_overflow;  // 1: the main stack ran into its guard (ports/cortex-m/fault.hpp)
};

// Records fault `exception` with its `status` in `record`, reading the stacked `frame` only if stacking succeeded.
inline void record_fault(FaultRecord& record, std::uint32_t exception, const FaultStatus& status,
                         const ExceptionFrame* frame, bool stack_overflow) {
  const bool counting = record.magic == FaultRecord::unreported || record.magic == FaultRecord::reported;
  const bool stacked = (status.cfsr & FaultStatus::stacking_errors) == 0;
  const ExceptionFrame registers = stacked ? *frame : ExceptionFrame{};
  record.count = counting ? record.count + 1 : 1;
  record.exception = exception;
  record.cfsr = status.cfsr;
  record.hfsr = status.hfsr;
  record.mmfar = status.mmfar;
  record.bfar = status.bfar;
  record.pc = registers.pc;
  record.lr = registers.lr;
  record.xpsr = registers.xpsr;
  record.stack_overflow = stack_overflow ? 1U : 0U;
  record.magic = FaultRecord::unreported;
}

// The fault `record` holds if the next start has not taken it yet, once. A record of garbage (power-on) becomes an
// empty one, so that the count starts from there.
inline std::optional<FaultRecord> take_fault(FaultRecord& record) {
  if (record.magic == FaultRecord::unreported) {
    const FaultRecord fault = record;
    record.magic = FaultRecord::reported;
    return fault;
  }
  if (record.magic != FaultRecord::reported) {
    record = FaultRecord{};
    record.magic = FaultRecord::reported;
  }
  return std::nullopt;
}

// take_fault() on the M4's record (fault.cpp): call once at start-up.
std::optional<FaultRecord> take_last_fault();

}  // namespace duet::stm32mp15
