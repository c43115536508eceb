#include "pil_command.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <exception>
#include <memory>
#include <string>

#include "duet/link/tcp.hpp"
#include "host_port_validator.hpp"
#include "pil_run.hpp"

namespace duet::cli {
namespace {

// HOST:PORT for one of the bridge's listeners. The bridge listens on 127.0.0.1 only unless told --expose, a
// decision `duet pil` leaves to whoever runs the bridge by hand.
CLI::Validator bridge_listen_validator() {
  return CLI::Validator(
      [](const std::string& text) {
        auto parsed = link::parse_host_port(text);
        if (!parsed) return parsed.error();
        if (parsed.value().host != "127.0.0.1") {
          return "'" + text +
                 "': the bridge listens on 127.0.0.1 only here (run duet-bridge --expose by hand to "
                 "reach it from the network)";
        }
        return std::string{};
      },
      "");
}

// Seconds of model time: a finite number above 0.
CLI::Validator positive_seconds_validator() {
  return CLI::Validator(
      [](const std::string& text) {
        double seconds = 0;
        std::size_t used = 0;
        try {
          seconds = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(seconds) || seconds <= 0) {
          return "'" + text + "' is not a positive number of seconds";
        }
        return std::string{};
      },
      "");
}

// "127.0.0.1:5555" for ":5555": the form duet-bridge takes. Precondition: the validator passed.
std::string normalised(const std::string& address) { return link::to_string(link::parse_host_port(address).value()); }

}  // namespace

Action define_pil_command(CLI::App& command) {
  auto options = std::make_shared<PilOptions>();
  command.add_option("firmware", options->firmware, "The firmware image (ELF) for mps2-an386")
      ->required()
      ->type_name("FIRMWARE.elf")
      ->check(CLI::ExistingFile);
  command.add_option("--plant", options->plant.name, "The plant: " + plant_list())
      ->capture_default_str()
      ->type_name("NAME");
  add_plant_options(command, options->plant);
  command
      .add_option_function<double>(
          "--duration", [options](const double& seconds) { options->duration_s = seconds; },
          "Seconds of model time, told to the firmware, which ends by itself then (default: until Ctrl-C)")
      ->type_name("S")
      ->check(positive_seconds_validator());
  command.add_flag("--lock-step", options->lock_step,
                   "The plant answers as fast as it can (default: it keeps real time, each tick at its time)");
  command
      .add_option("--icount-shift", options->icount_shift,
                  "QEMU's -icount shift: one instruction takes 2^N ns of the emulated clock")
      ->capture_default_str()
      ->type_name("N")
      ->check(CLI::Range(0, 10));
  command.add_option("--xcp", options->xcp, "Where the bridge takes an XCP master (TCP and UDP)")
      ->capture_default_str()
      ->type_name("HOST:PORT")
      ->check(bridge_listen_validator());
  command
      .add_option("--websocket", options->websocket,
                  "Where the bridge offers the application channel to WebSocket clients")
      ->capture_default_str()
      ->type_name("HOST:PORT")
      ->check(bridge_listen_validator());
  command
      .add_option("--plant-control", options->plant_control,
                  "HOST:PORT on this machine where the plant takes disturbances (push, restart) from the dashboards; "
                  "port 0 takes a free port (printed)")
      ->capture_default_str()
      ->type_name("HOST:PORT")
      ->check(host_port_validator());
  command.add_flag(
      "--no-bridge", [options](std::int64_t) { options->bridge = false; },
      "No bridge: the firmware's XCP and application channels stay unix sockets (printed)");
  command
      .add_option("--bridge", options->bridge_program,
                  "The duet-bridge program (default: the one built beside duet, else duet-bridge on PATH)")
      ->type_name("PATH");
  command.add_option("--qemu", options->qemu, "The emulator")->capture_default_str()->type_name("PATH");
  command.add_option("--csv", options->recording.csv, "Write the plant's own quantities, a row per tick, to FILE")
      ->type_name("FILE");
  command.add_option("--plot", options->recording.plot, "The same as an SVG plot, a panel per unit")->type_name("FILE");
  command
      .add_option("--mdf", options->recording.mdf,
                  "The same as an MDF 4 file, streamed: a group of the plant's quantities, and one per event of "
                  "--signal")
      ->type_name("FILE");
  command
      .add_option("--signal", options->firmware_signals.signals,
                  "A firmware signal to record into --mdf by XCP through the bridge, sampled on EVENT (default "
                  "--event); repeatable")
      ->type_name("NAME[@EVENT]");
  command.add_option("--event", options->firmware_signals.event, "The event of a --signal without @EVENT")
      ->type_name("EVENT");
  command.add_option("--a2l", options->firmware_signals.a2l_file, "The firmware's A2L, for --signal")
      ->type_name("FILE")
      ->check(CLI::ExistingFile);
  command.add_option("--console", options->console, "Write every line of the firmware's console to FILE")
      ->type_name("FILE");
  command.get_option("--bridge")->excludes("--no-bridge");
  // The firmware's signals go into the MDF file, reached by XCP through the bridge and named by the A2L.
  command.get_option("--signal")->needs("--mdf")->needs("--a2l")->excludes("--no-bridge");
  command.get_option("--event")->needs("--signal");
  command.get_option("--a2l")->needs("--signal");
  return [options](Streams streams) {
    if (auto misuse = plant_options_misuse(options->plant)) {
      streams.err << "duet pil: " << *misuse << '\n';
      return ExitCode::usage;
    }
    PilOptions chosen = *options;
    chosen.xcp = normalised(chosen.xcp);
    chosen.websocket = normalised(chosen.websocket);
    return run_pil(chosen, streams);
  };
}

}  // namespace duet::cli
