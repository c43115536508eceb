#include "plant_command.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <memory>
#include <ostream>
#include <string>

#include "duet/link/serve.hpp"
#include "duet/link/tcp.hpp"
#include "host_port_validator.hpp"
#include "plant_choice.hpp"
#include "plant_control_endpoint.hpp"
#include "recording_plant.hpp"

namespace duet::cli {
namespace {

struct ServeOptions {
  PlantChoice plant;
  std::string listen = "127.0.0.1:" + std::to_string(link::default_port);
  bool once = false;
  double timeout_s = 10;
  RecordingFiles recording;  // the plant's observables, a row per TICK, written when a session ends
  std::string plant_control = "127.0.0.1:0";
};

std::string describe(const link::ServeSummary& summary) {
  const bool lock_step = summary.hello.mode == link::LinkMode::lock_step;
  return std::to_string(summary.ticks) + " ticks, " + std::to_string(summary.interrupts) + " interrupts, " +
         std::to_string(summary.writes) + " writes, " + std::to_string(summary.reads) + " reads (" +
         (lock_step ? "lock-step" : "real time") + ", base period " +
         std::to_string(summary.hello.base_period_ns / 1000) + " us)" +
         (!summary.plant_stop.empty() ? "; " + summary.plant_stop
          : summary.said_bye          ? ""
                                      : ", ended without BYE");
}

constexpr std::string_view prefix = "duet plant serve: ";

// The session's recording, as --csv and --plot ask.
bool write_recording(const ServeOptions& options, const RecordingPlant& plant, const std::string& peer,
                     Streams streams) {
  const model::Recording& recording = plant.recording();
  if (plant.truncated()) {
    streams.err << prefix << peer << ": the recording holds the first " << recording.time_s.size() << " ticks only\n";
  }
  const Status written =
      write_recording_files(recording, options.recording, "plant " + options.plant.name + ", served to " + peer);
  if (!written) streams.err << prefix << written.error() << '\n';
  return written.ok();
}

ExitCode serve_plant(const ServeOptions& options, Streams streams) {
  auto chosen = choose_plant(options.plant, log_lines_to(streams.err));
  if (!chosen) {
    streams.err << prefix << chosen.error() << '\n';
    return ExitCode::failure;
  }
  if (Status created = create_recording_files(options.recording); !created) {
    streams.err << prefix << created.error() << '\n';
    return ExitCode::failure;
  }
  auto address = link::parse_host_port(options.listen);  // checked by the option's validator already
  if (!address) {
    streams.err << prefix << address.error() << '\n';
    return ExitCode::usage;
  }
  auto listener = link::TcpListener::open(address.value());
  if (!listener) {
    streams.err << prefix << listener.error() << '\n';
    return ExitCode::failure;
  }
  auto control = PlantControlEndpoint::open(chosen.value(), options.plant.name, options.plant_control);
  if (!control) {
    streams.err << prefix << control.error() << '\n';
    return ExitCode::failure;
  }
  const link::Timeout session_timeout =
      options.timeout_s == 0 ? link::no_timeout
                             : link::Timeout{static_cast<link::Timeout::rep>(std::ceil(options.timeout_s * 1000))};
  streams.out << "plant " << options.plant.name << " listening on " << link::to_string(listener.value().address())
              << std::endl;  // a line scripts wait for: flushed now
  if (!control.value().address().empty()) {
    streams.out << "plant " << options.plant.name << " control on " << control.value().address() << " ("
                << control.value().actions() << ": duet monitor --plant-control, or JSON lines, docs/LINK.md)"
                << std::endl;
  }
  for (;;) {
    auto accepted = listener.value().accept(link::no_timeout, session_timeout);
    if (!accepted) {
      streams.err << prefix << accepted.error() << '\n';
      return ExitCode::failure;
    }
    auto made = chosen.value().make();
    if (!made) {
      streams.err << prefix << made.error() << '\n';
      return ExitCode::failure;
    }
    RecordingPlant plant{control.value().controlled(std::move(made).value()), options.recording.any()};
    auto served = link::serve(plant, *accepted.value().stream);
    if (served) {
      streams.out << "served " << accepted.value().peer << ": " << describe(served.value()) << std::endl;
    } else {
      streams.err << prefix << accepted.value().peer << ": " << served.error() << std::endl;
    }
    // Written for a failed session too: how it went up to the failure is what one wants to look at.
    const bool written = write_recording(options, plant, accepted.value().peer, streams);
    if (options.once) return served && written ? ExitCode::success : ExitCode::failure;
  }
}

}  // namespace

Action define_plant_command(CLI::App& command) {
  auto options = std::make_shared<ServeOptions>();
  command.require_subcommand(1);
  CLI::App* serve = command.add_subcommand(
      "serve", "Serve a simulated plant over the virtual-hardware link to firmware that connects over TCP");
  serve->add_option("name", options->plant.name, "The plant: " + plant_list())->required()->type_name("NAME");
  add_plant_options(*serve, options->plant);
  serve
      ->add_option("--listen", options->listen,
                   "HOST:PORT to listen on; port 0 takes a free port (the line printed says which)")
      ->capture_default_str()
      ->type_name("HOST:PORT")
      ->check(host_port_validator());
  serve->add_flag("--once", options->once, "Serve one firmware, then exit (with 1 if that session failed)");
  serve
      ->add_option("--timeout", options->timeout_s,
                   "Seconds to wait for the firmware's next frame before giving up on it (0: forever)")
      ->capture_default_str()
      ->type_name("S")
      ->check(CLI::Range(0.0, 1e6));
  serve
      ->add_option("--csv", options->recording.csv,
                   "Write the plant's own quantities, a row per TICK, to FILE when a session ends (the last session's)")
      ->type_name("FILE");
  serve->add_option("--plot", options->recording.plot, "The same as an SVG plot, a panel per unit")->type_name("FILE");
  serve->add_option("--mdf", options->recording.mdf, "The same as an MDF 4 file")->type_name("FILE");
  serve
      ->add_option("--plant-control", options->plant_control,
                   "HOST:PORT on this machine where the plant takes disturbances (push, restart) while a firmware "
                   "is served; port 0 takes a free port (a line says which)")
      ->capture_default_str()
      ->type_name("HOST:PORT")
      ->check(host_port_validator());
  return [options](Streams streams) {
    if (auto misuse = plant_options_misuse(options->plant)) {
      streams.err << prefix << *misuse << '\n';
      return ExitCode::usage;
    }
    return serve_plant(*options, streams);
  };
}

}  // namespace duet::cli
