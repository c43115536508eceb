#pragma once
// `duet pil FIRMWARE.elf`: processor in the loop. The firmware runs on QEMU's emulated Cortex-M4 (mps2-an386)
// against a simulated plant served in this process over the virtual-hardware link, with duet-bridge relaying XCP
// and the application channel, in real time or lock-step, and the run ends with a summary (docs/LINK.md).

#include "subcommand.hpp"

namespace duet::cli {

Action define_pil_command(CLI::App& command);

}  // namespace duet::cli
