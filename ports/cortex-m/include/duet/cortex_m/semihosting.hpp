#pragma once
// ARM semihosting: requests to a debugger or emulator attached to the core (here: QEMU with -semihosting-config).
// Without one attached, the BKPT instruction these use faults: only a board that is known to run under one uses them.

namespace duet::cortex_m::semihosting {

// SYS_EXIT_EXTENDED with reason ADP_Stopped_ApplicationExit: QEMU exits with `exit_code` (0-255).
[[noreturn]] void exit(int exit_code);

}  // namespace duet::cortex_m::semihosting
