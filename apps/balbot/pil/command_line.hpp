#pragma once
// The firmware's command line, as QEMU passes it through semihosting (-semihosting-config arg=...): the program's
// name, then --link DIRECTORY (where the plant's named pipes to_plant and from_plant are) and [--duration SECONDS]
// with at most three decimals.

#include <cstdint>
#include <string_view>

#include "duet/base/text_buffer.hpp"

namespace balbot::pil {

struct CommandLine {
  std::uint64_t duration_ms = 0;  // 0: run until stopped
  // The pipes' paths, each NUL-terminated after its view.
  std::string_view to_plant;
  std::string_view from_plant;
  duet::TextBuffer<120> problem;  // empty: the command line was good
};

CommandLine parse_command_line(std::string_view text);

}  // namespace balbot::pil
