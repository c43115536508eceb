// duet-bridge: relays XCP between the real-time core's channel and a master on TCP (relay.hpp), and offers the
// application channel over WebSocket and as CSV (app_service.hpp); docs/BRIDGE.md.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <thread>

#include "app_service.hpp"
#include "duet/dashboard/static_files.hpp"
#include "duet/version.hpp"
#include "relay.hpp"

namespace {

// The machine the program runs on as the kernel reports it: "armv7l" on the board and under qemu-arm.
std::string machine() {
  utsname name{};
  return uname(&name) == 0 ? std::string{name.machine} : std::string{"unknown"};
}

struct Endpoint {
  std::string address;
  std::uint16_t port = 0;
};

// "address:port" for option `option`; localhost unless `expose`.
duet::Result<Endpoint> parse_endpoint(const std::string& option, const std::string& text, bool expose) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos) return duet::Failure{option + " '" + text + "': expected address:port"};
  Endpoint endpoint{text.substr(0, colon)};
  try {
    const unsigned long port = std::stoul(text.substr(colon + 1));
    if (port > 65535) throw std::out_of_range{"port"};
    endpoint.port = static_cast<std::uint16_t>(port);
  } catch (const std::exception&) {
    return duet::Failure{option + " '" + text + "': the port is not a number from 0 to 65535"};
  }
  if (endpoint.address != "127.0.0.1" && !expose) {
    return duet::Failure{option + " " + text + " would reach beyond this machine: add --expose to mean it"};
  }
  return endpoint;
}

std::string relay_status_json(const duet::bridge::Relay& relay) {
  const duet::bridge::RelayCounters counters = relay.counters();
  return nlohmann::json{{"xcp",
                         {{"channel_open", relay.channel_open()},
                          {"master_connected", relay.master_connected()},
                          {"frames_to_master", counters.frames_to_master},
                          {"frames_to_slave", counters.frames_to_slave},
                          {"bytes_to_master", counters.bytes_to_master},
                          {"bytes_to_slave", counters.bytes_to_slave},
                          {"daq_frames_dropped", counters.daq_frames_dropped},
                          {"answers_dropped", counters.answers_dropped},
                          {"frames_without_master", counters.frames_without_master},
                          {"commands_refused", counters.commands_refused},
                          {"commands_unanswered", counters.commands_unanswered},
                          {"garbage_bytes", counters.garbage_bytes},
                          {"channel_opens", counters.channel_opens},
                          {"masters_served", counters.masters_served},
                          {"masters_refused", counters.masters_refused},
                          {"responses", counters.responses},
                          {"latency_mean_us", counters.latency_mean_us},
                          {"latency_max_us", counters.latency_max_us}}}}
      .dump();
}

// Waits for SIGINT or SIGTERM (blocked in every thread), logging `status()` on SIGUSR1.
void wait_for_signals(const sigset_t& signals, const std::function<std::string()>& status) {
  for (;;) {
    int number = 0;
    if (sigwait(&signals, &number) != 0) return;
    if (number != SIGUSR1) return;
    std::cerr << "duet-bridge: " << status() << std::endl;
  }
}

int run(int argc, char** argv) {
  CLI::App app{
      "duet-bridge: relays XCP between the real-time core's channel and one master on TCP, and offers the "
      "application channel over WebSocket and as CSV",
      "duet-bridge"};
  app.set_version_flag("--version", "duet-bridge " + std::string{duet::version} + " on " + machine());
  app.set_config("--config", "", "A file of option = value lines with the options' long names");
  std::string channel;
  std::string listen = "127.0.0.1:5555";
  std::string app_channel;
  std::string websocket = "127.0.0.1:8765";
  bool no_websocket = false;
  std::string web = duet::dashboard::default_web_root().string();
  bool csv = false;
  std::string plant_control;
  bool expose = false;
  bool verbose = false;
  app.add_option("--channel", channel, "The XCP channel: tty:/dev/ttyRPMSG0, unix:/path or tcp://host:port");
  app.add_option("--listen", listen, "Address:port for the XCP master (localhost unless --expose)");
  app.add_option("--app-channel", app_channel, "The application channel: tty:/dev/ttyRPMSG1, unix:/path or tcp://...");
  app.add_option("--websocket", websocket, "Address:port for WebSocket clients (localhost unless --expose)");
  app.add_flag("--no-websocket", no_websocket, "Offer the application channel as CSV only");
  app.add_option("--web", web, "The dashboard's built files, served on the WebSocket's port")
      ->capture_default_str()
      ->check(CLI::ExistingDirectory);
  app.add_option("--plant-control", plant_control,
                 "A simulated plant's control endpoint (duet pil prints it): the dashboard may push and restart it");
  app.add_flag("--csv", csv, "Print the application's telemetry as CSV on stdout; name=value lines on stdin set");
  app.add_flag("--expose", expose, "Allow listening on addresses other than 127.0.0.1 (the network)");
  app.add_flag("--verbose", verbose, "Log every master that connects and leaves");
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& success) {
    return app.exit(success);
  } catch (const CLI::ParseError& error) {
    std::cerr << "duet-bridge: " << error.what() << ". See 'duet-bridge --help'.\n";
    return 2;
  }
  if (channel.empty() && app_channel.empty()) {
    std::cerr
        << "duet-bridge: nothing to relay: give --channel (XCP) and/or --app-channel. See 'duet-bridge --help'.\n";
    return 2;
  }

  std::optional<duet::bridge::Relay> relay;
  if (!channel.empty()) {
    auto address = duet::bridge::parse_channel(channel);
    auto endpoint = parse_endpoint("--listen", listen, expose);
    if (!address || !endpoint) {
      std::cerr << "duet-bridge: " << (!address ? address.error() : endpoint.error()) << '\n';
      return 2;
    }
    duet::bridge::RelayOptions options{.channel = address.value(), .channel_uri = channel, .verbose = verbose};
    options.listen_address = endpoint.value().address;
    options.listen_port = endpoint.value().port;
    relay.emplace(options);
  }
  std::optional<duet::bridge::AppService> service;
  if (!app_channel.empty()) {
    auto address = duet::bridge::parse_channel(app_channel);
    auto endpoint = parse_endpoint("--websocket", websocket, expose);
    if (!address || !endpoint) {
      std::cerr << "duet-bridge: " << (!address ? address.error() : endpoint.error()) << '\n';
      return 2;
    }
    duet::bridge::AppServiceOptions options;
    options.channel = address.value();
    options.channel_uri = app_channel;
    options.listen_address = endpoint.value().address;
    options.websocket_port = endpoint.value().port;
    options.websocket = !no_websocket;
    options.web_root = web;
    options.csv = csv;
    options.verbose = verbose;
    if (!plant_control.empty()) {
      // Where to connect to, not to listen on: any address is the user's choice.
      auto control = parse_endpoint("--plant-control", plant_control, true);
      if (!control) {
        std::cerr << "duet-bridge: " << control.error() << '\n';
        return 2;
      }
      options.plant_control = duet::dashboard::PlantControlAddress{control.value().address, control.value().port};
    }
    if (relay) options.extra_status = [&relay] { return relay_status_json(*relay); };
    service.emplace(options);
  }

  // A reader of the CSV (or a peer of a channel) that goes away is an error to report, not a silent end.
  ::signal(SIGPIPE, SIG_IGN);
  // Signals go to the relay's signalfd, or to sigwait here; no thread may take them the default way.
  sigset_t signals;
  sigemptyset(&signals);
  for (int number : {SIGINT, SIGTERM, SIGUSR1}) sigaddset(&signals, number);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  if (relay) {
    if (auto started = relay->start(); !started) {
      std::cerr << "duet-bridge: " << started.error() << '\n';
      return 1;
    }
  }
  std::thread service_thread;
  duet::Status service_ended = duet::done();
  if (service) {
    if (auto started = service->start(); !started) {
      std::cerr << "duet-bridge: " << started.error() << '\n';
      return 1;
    }
    if (!no_websocket) {
      const std::string address =
          websocket.substr(0, websocket.rfind(':')) + ':' + std::to_string(service->websocket_port());
      std::cerr << "duet-bridge: WebSocket clients on " << address << std::endl;
      std::cerr << "duet-bridge: dashboard on http://" << address << "/" << std::endl;
    }
    service_thread = std::thread{[&service, &service_ended] {
      service_ended = service->run();
      // Ended by itself (its CSV output failed): the whole bridge stops, the way a SIGTERM stops it.
      if (!service_ended) ::kill(::getpid(), SIGTERM);
    }};
  }
  const auto status = [&] {
    std::string text = relay ? relay->status() : std::string{};
    if (service) text += (text.empty() ? "" : "; ") + std::string{"application channel "} + service->status();
    return text;
  };
  if (relay) {
    relay->run(true,
               service ? std::function<std::string()>{[&service] { return "application channel " + service->status(); }}
                       : std::function<std::string()>{});
  } else {
    wait_for_signals(signals, status);
  }
  if (service) {
    service->stop();
    service_thread.join();
  }
  if (!service_ended) std::cerr << "duet-bridge: " << service_ended.error() << '\n';
  std::cerr << "duet-bridge: stopped; " << status() << '\n';
  return service_ended ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& error) {
    std::cerr << "duet-bridge: internal error: " << error.what() << '\n';
    return 1;
  }
}
