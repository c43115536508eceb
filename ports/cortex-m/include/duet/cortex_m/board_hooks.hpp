#pragma once
// What the generic Cortex-M code needs from the board it runs on. Each board port defines these functions once.

#include <string_view>

#include "duet/cortex_m/fault.hpp"

namespace duet::cortex_m {

// Writes `text` to the board's console as it is, polling: for start-up messages and fault reports, never for code
// that must not wait. Under QEMU it never waits; on hardware it waits for the UART or the trace buffer.
void console_write(std::string_view text);

// Stops the firmware for good with `exit_code` (0 for success). Under QEMU, QEMU exits with that code; on hardware the
// core parks with interrupts disabled until its supervisor (a debugger, Linux's remoteproc) restarts it.
[[noreturn]] void halt(int exit_code);

// What the board does when the core faults (fault.hpp): its outputs to their safe state first, then the fault recorded
// and reported, then halt(128 + exception). Runs on the fault stack with interrupts masked and the MPU off, so it may
// use neither the main stack nor anything a fault could have left half-written that it cannot check.
[[noreturn]] void on_fault(const Fault& fault);

}  // namespace duet::cortex_m
