#include "monitor_command.hpp"

#include <CLI/CLI.hpp>
#include <boost/asio.hpp>

#include <memory>
#include <string>

#include "duet/dashboard/static_files.hpp"
#include "duet/link/tcp.hpp"
#include "duet/monitor/monitor_target.hpp"
#include "duet/support/text_file.hpp"
#include "host_port_validator.hpp"
#include "page_server.hpp"

namespace duet::cli {
namespace {

struct MonitorCommandOptions {
  std::string xcp;
  std::string a2l_file;
  std::vector<std::string> signals;
  std::string event;
  std::string listen = "127.0.0.1:8766";
  bool expose = false;
  std::string web = dashboard::default_web_root().string();
  int timeout_ms = 1000;
  std::string plant_control;  // HOST:PORT
};

ExitCode fail(Streams streams, const std::string& message) {
  streams.err << "duet monitor: " << message << '\n';
  return ExitCode::failure;
}

ExitCode run_monitor(const MonitorCommandOptions& options, Streams streams) {
  const auto address = listen_address(options.listen, options.expose, "duet monitor", streams.err);
  if (!address) return ExitCode::usage;
  const link::HostPort& listen = *address;
  auto text = read_text_file(options.a2l_file);
  if (!text) return fail(streams, text.error());
  auto a2l = xcp::host::read_a2l(text.value(), options.a2l_file);
  if (!a2l) return fail(streams, a2l.error());
  for (const std::string& warning : a2l.value().warnings) streams.err << "duet monitor: warning: " << warning << '\n';
  xcp::host::Endpoint target = a2l.value().transport;
  if (!options.xcp.empty()) {
    auto parsed = xcp::host::parse_endpoint(options.xcp);
    if (!parsed) return fail(streams, "--xcp " + parsed.error());
    target = parsed.value();
  }

  std::optional<dashboard::PlantControlAddress> plant_control;
  if (!options.plant_control.empty()) {
    const link::HostPort control = link::parse_host_port(options.plant_control).value();  // checked by the validator
    plant_control = dashboard::PlantControlAddress{control.host, control.port};
  }

  // Member by member: GCC 12 at -O3 takes the strings of a designated initializer for uninitialised.
  monitor::MonitorOptions monitor_options;
  monitor_options.target = target;
  monitor_options.a2l = std::move(a2l).value();
  monitor_options.signals = options.signals;
  monitor_options.event = options.event;
  monitor_options.server.address = listen.host;
  monitor_options.server.port = listen.port;
  monitor_options.server.web_root = options.web;
  monitor_options.server.log_name = "duet monitor";
  monitor_options.plant_control = plant_control;
  monitor_options.timeout_ms = options.timeout_ms;
  boost::asio::io_context io;
  auto monitor = monitor::MonitorTarget::create(io, std::move(monitor_options));
  if (!monitor) return fail(streams, monitor.error());
  StopSignals stop;
  if (Status started = monitor.value()->start(); !started) return fail(streams, started.error());
  streams.out << "duet monitor: dashboard on http://" << listen.host << ':' << monitor.value()->port()
              << "/ for the target at " << xcp::host::to_string(target) << " (Ctrl-C stops)" << std::endl;
  serve_until_stopped(io, stop);
  monitor.value()->stop();
  streams.out << "duet monitor: stopped\n";
  return ExitCode::success;
}

}  // namespace

Action define_monitor_command(CLI::App& command) {
  auto options = std::make_shared<MonitorCommandOptions>();
  command.add_option("--xcp", options->xcp,
                     "The target's XCP: tcp://host:port or udp://host:port (default: the A2L's)");
  command.add_option("--a2l", options->a2l_file, "The target's A2L file (signals, parameters, events)")
      ->required()
      ->check(CLI::ExistingFile);
  command.add_option("--signal", options->signals, "A MEASUREMENT to sample by DAQ (repeat; default: every one)");
  command.add_option("--event", options->event, "The DAQ event, by name or number (default: the fastest periodic one)");
  command.add_option("--listen", options->listen, "Address:port of the dashboard (HTTP and WebSocket)")
      ->capture_default_str()
      ->check(host_port_validator());
  command.add_flag("--expose", options->expose, "Allow listening on addresses other than 127.0.0.1 (the network)");
  command.add_option("--web", options->web, "The dashboard's built files (web/dist)")
      ->capture_default_str()
      ->check(CLI::ExistingDirectory);
  command
      .add_option("--plant-control", options->plant_control,
                  "A simulated plant's control endpoint (duet pil prints it): the page may push and restart it")
      ->type_name("HOST:PORT")
      ->check(host_port_validator());
  command.add_option("--timeout-ms", options->timeout_ms, "How long an XCP command may wait for its answer")
      ->capture_default_str()
      ->check(CLI::Range(10, 60'000));
  return [options](Streams streams) { return run_monitor(*options, streams); };
}

}  // namespace duet::cli
