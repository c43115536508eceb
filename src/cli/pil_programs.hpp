#pragma once
// The command lines `duet pil` runs: QEMU's emulated Cortex-M4 (mps2-an386) with the firmware, its UARTs wired to
// the bridge, the plant and duet, and duet-bridge (docs/LINK.md, "Processor in the loop").

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace duet::cli {

struct QemuSetup {
  std::string qemu = "qemu-system-arm";
  std::string firmware;  // the ELF image
  int icount_shift = 2;
  std::optional<double> duration_s;  // passed to the firmware as its arguments "--duration S" (semihosting)
  std::filesystem::path folder;      // where the UARTs' sockets and the plant's pipes are
};

// The emulator's command line. UART0: XCP (folder/xcp.sock), UART1: the application channel (folder/app.sock),
// both unix sockets QEMU listens on without waiting; UART2: unused; UART3: the firmware's console, on QEMU's standard
// output. The plant link is the pipes in `folder` (link::NamedPipes), which the firmware's "--link FOLDER" names.
[[nodiscard]] std::vector<std::string> qemu_command(const QemuSetup& setup);

struct BridgeSetup {
  std::string bridge = "duet-bridge";
  std::filesystem::path folder;  // holds QEMU's xcp.sock and app.sock
  std::string xcp;               // HOST:PORT for the XCP master
  std::string websocket;         // HOST:PORT for WebSocket clients
  std::string plant_control;     // HOST:PORT of the plant's control endpoint, or empty
};

[[nodiscard]] std::vector<std::string> bridge_command(const BridgeSetup& setup);

// duet-bridge of the build tree `duet` comes from (`duet_program`'s folder/../bridge/duet-bridge, for an absolute
// `duet_program`) when it is there, else the name alone, to be looked up on PATH.
[[nodiscard]] std::string default_bridge(const std::filesystem::path& duet_program);

// The shortest text that reads back as `value` ("3", "2.5", "0.1").
[[nodiscard]] std::string shortest(double value);

}  // namespace duet::cli
