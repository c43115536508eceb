// duet-bridge: relays XCP between the real-time core's channel and a master on TCP (see relay.hpp, docs/BRIDGE.md).
#include <CLI/CLI.hpp>
#include <sys/utsname.h>

#include <exception>
#include <fstream>
#include <iostream>
#include <string>

#include "duet/version.hpp"
#include "relay.hpp"

namespace {

// The machine the program runs on as the kernel reports it: "armv7l" on the board and under qemu-arm.
std::string machine() {
  utsname name{};
  return uname(&name) == 0 ? std::string{name.machine} : std::string{"unknown"};
}

int run(int argc, char** argv) {
  CLI::App app{"duet-bridge: relays XCP between the real-time core's channel and one master on TCP", "duet-bridge"};
  app.set_version_flag("--version", "duet-bridge " + std::string{duet::version} + " on " + machine());
  app.set_config("--config", "", "A file of option = value lines (channel, listen, expose, verbose)");
  std::string channel;
  std::string listen = "127.0.0.1:5555";
  bool expose = false;
  bool verbose = false;
  app.add_option("--channel", channel, "The XCP channel: tty:/dev/ttyRPMSG0, unix:/path or tcp://host:port")
      ->required();
  app.add_option("--listen", listen, "Address:port for the master (localhost unless --expose)");
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
  auto address = duet::bridge::parse_channel(channel);
  if (!address) {
    std::cerr << "duet-bridge: " << address.error() << '\n';
    return 2;
  }
  const std::size_t colon = listen.rfind(':');
  if (colon == std::string::npos) {
    std::cerr << "duet-bridge: --listen '" << listen << "': expected address:port\n";
    return 2;
  }
  duet::bridge::RelayOptions options{.channel = address.value(), .channel_uri = channel, .verbose = verbose};
  options.listen_address = listen.substr(0, colon);
  try {
    options.listen_port = static_cast<std::uint16_t>(std::stoul(listen.substr(colon + 1)));
  } catch (const std::exception&) {
    std::cerr << "duet-bridge: --listen '" << listen << "': the port is not a number\n";
    return 2;
  }
  if (options.listen_address != "127.0.0.1" && !expose) {
    std::cerr << "duet-bridge: --listen " << listen << " would reach beyond this machine: add --expose to mean it\n";
    return 2;
  }
  duet::bridge::Relay relay{options};
  if (auto started = relay.start(); !started) {
    std::cerr << "duet-bridge: " << started.error() << '\n';
    return 1;
  }
  relay.run(true);
  std::cerr << "duet-bridge: stopped; " << relay.status() << '\n';
  return 0;
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
