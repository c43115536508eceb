#include "duet/cortex_m/semihosting.hpp"

#include <cstdint>

namespace duet::cortex_m::semihosting {
namespace {

// Semihosting operations and reasons, from ARM's "Semihosting for AArch32 and AArch64" specification.
constexpr std::uint32_t sys_open = 0x01;
constexpr std::uint32_t sys_close = 0x02;
constexpr std::uint32_t sys_write = 0x05;
constexpr std::uint32_t sys_read = 0x06;
constexpr std::uint32_t sys_get_cmdline = 0x15;
constexpr std::uint32_t sys_exit_extended = 0x20;
constexpr std::uint32_t application_exit = 0x20026;

std::uint32_t call(std::uint32_t operation, const void* parameters) {
  register std::uint32_t r0 asm("r0") = operation;
  register const void* r1 asm("r1") = parameters;
  asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

std::uint32_t address(const void* pointer) {
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(pointer));
}

}  // namespace

int open(std::string_view path, FileMode mode) {
  const std::uint32_t parameters[3] = {address(path.data()), static_cast<std::uint32_t>(mode),
                                       static_cast<std::uint32_t>(path.size())};
  return static_cast<int>(call(sys_open, parameters));
}

std::size_t write(int handle, std::span<const std::uint8_t> bytes) {
  const std::uint32_t parameters[3] = {static_cast<std::uint32_t>(handle), address(bytes.data()),
                                       static_cast<std::uint32_t>(bytes.size())};
  const std::uint32_t not_written = call(sys_write, parameters);
  return not_written > bytes.size() ? 0 : bytes.size() - not_written;
}

std::size_t read(int handle, std::span<std::uint8_t> bytes) {
  const std::uint32_t parameters[3] = {static_cast<std::uint32_t>(handle), address(bytes.data()),
                                       static_cast<std::uint32_t>(bytes.size())};
  const std::uint32_t not_read = call(sys_read, parameters);
  return not_read > bytes.size() ? 0 : bytes.size() - not_read;
}

void close(int handle) {
  const std::uint32_t parameters[1] = {static_cast<std::uint32_t>(handle)};
  call(sys_close, parameters);
}

std::string_view command_line(std::span<char> buffer) {
  if (buffer.empty()) return {};
  std::uint32_t parameters[2] = {address(buffer.data()), static_cast<std::uint32_t>(buffer.size())};
  if (call(sys_get_cmdline, parameters) != 0 || parameters[1] >= buffer.size()) return {};
  return {buffer.data(), parameters[1]};
}

void exit(int exit_code) {
  const std::uint32_t parameters[2] = {application_exit, static_cast<std::uint32_t>(exit_code)};
  call(sys_exit_extended, parameters);
  for (;;) {  // not reached under an emulator; a debugger may resume, and then there is nothing left to run
    asm volatile("wfi");
  }
}

}  // namespace duet::cortex_m::semihosting
