#pragma once
// `duet pil`'s run: the firmware on QEMU's emulated Cortex-M4, the plant served in a thread over the link, the
// bridge relaying XCP and the application channel; watched until the firmware ends, the plant session fails or a
// signal says stop; then every child stopped and reaped, and a summary (docs/LINK.md, "Processor in the loop").

#include <cstdint>
#include <optional>
#include <string>

#include "pil_firmware_recording.hpp"
#include "plant_choice.hpp"
#include "recording_plant.hpp"
#include "subcommand.hpp"

namespace duet::cli {

struct PilOptions {
  std::string firmware;  // the ELF image
  PlantChoice plant{.name = "balbot"};
  std::optional<double> duration_s;  // told to the firmware; none: until a signal
  bool lock_step = false;            // false: the plant keeps real time
  int icount_shift = 2;
  std::string xcp = "127.0.0.1:5555";         // where the bridge takes an XCP master
  std::string websocket = "127.0.0.1:8765";   // where the bridge takes WebSocket clients
  std::string plant_control = "127.0.0.1:0";  // where the plant takes disturbances (the dashboards relay them)
  bool bridge = true;
  std::string bridge_program;  // empty: default_bridge()
  std::string qemu = "qemu-system-arm";
  RecordingFiles recording;          // the plant's observables per tick
  FirmwareSignals firmware_signals;  // recorded into recording.mdf over XCP, if any
  std::string console;               // every line of the firmware's console, if given
};

// Blocks until the run is over. SIGINT and SIGTERM end it in order while it runs. Exit codes: success when the
// firmware ended well or a signal stopped a healthy run; failure otherwise, with messages on streams.err.
[[nodiscard]] ExitCode run_pil(const PilOptions& options, Streams streams);

}  // namespace duet::cli
