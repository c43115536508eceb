#pragma once
// ARM semihosting: requests to a debugger or emulator attached to the core (here: QEMU with -semihosting-config).
// Without one attached, the BKPT instruction these use faults: only a board that is known to run under one uses them.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace duet::cortex_m::semihosting {

// SYS_GET_CMDLINE: the command line the emulator passes (QEMU: -semihosting-config arg=...,arg=..., joined by
// spaces), in `buffer`; empty if there is none or it does not fit.
std::string_view command_line(std::span<char> buffer);

// Files of the host (QEMU: of the machine it runs on, relative to its working directory). A handle is -1 if the
// file could not be opened. Each call blocks the core until the host's system call returns, which under QEMU takes
// no emulated time: a way to exchange data with a host program at the speed of a pipe, without a device model.
enum class FileMode : std::uint32_t { read_binary = 1, write_binary = 5 };  // fopen's "rb" and "wb"
// `path` must end with a NUL character that the view does not include.
[[nodiscard]] int open(std::string_view path, FileMode mode);
// The bytes written, read: fewer than asked if the file ended or failed (a read of 0 bytes from a pipe: its writer
// closed it). A read returns what a single read of the host gave, which may be less than asked.
std::size_t write(int handle, std::span<const std::uint8_t> bytes);
std::size_t read(int handle, std::span<std::uint8_t> bytes);
void close(int handle);

// SYS_EXIT_EXTENDED with reason ADP_Stopped_ApplicationExit: QEMU exits with `exit_code` (0-255).
[[noreturn]] void exit(int exit_code);

}  // namespace duet::cortex_m::semihosting
