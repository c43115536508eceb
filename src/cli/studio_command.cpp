#include "studio_command.hpp"

#include <CLI/CLI.hpp>
#include <boost/asio.hpp>

#include <memory>
#include <string>

#include "duet/dashboard/static_files.hpp"
#include "duet/link/tcp.hpp"
#include "duet/studio/studio.hpp"
#include "duet/xcp/host/endpoint.hpp"
#include "host_port_validator.hpp"
#include "page_server.hpp"

namespace duet::cli {
namespace {

struct StudioCommandOptions {
  std::string model;
  std::string plant = "none";
  std::string scenario;
  double duration_s = 5;
  std::string xcp;
  std::string listen = "127.0.0.1:8767";
  bool expose = false;
  std::string web = dashboard::default_web_root().string();
};

ExitCode run_studio(const StudioCommandOptions& options, Streams streams) {
  const auto address = listen_address(options.listen, options.expose, "duet studio", streams.err);
  if (!address) return ExitCode::usage;
  const link::HostPort& listen = *address;
  // The page names plants and scenarios by their paths from the model's folder; the command line may name them
  // anywhere, and the server takes those as given.
  auto beside = [&options](const std::string& file) {
    const std::filesystem::path relative =
        std::filesystem::path{file}.lexically_relative(std::filesystem::path{options.model}.parent_path());
    return relative.empty() || relative.string().starts_with("..") ? file : relative.string();
  };
  // Member by member: GCC 12 at -O3 takes nested braced options for read before they are written.
  studio::StudioOptions studio_options;
  studio_options.model = options.model;
  studio_options.server.address = listen.host;
  studio_options.server.port = listen.port;
  studio_options.server.web_root = options.web;
  studio_options.server.log_name = "duet studio";
  studio_options.plant = options.plant.ends_with(".yaml") ? beside(options.plant) : options.plant;
  studio_options.scenario = options.scenario.empty() ? std::string{} : beside(options.scenario);
  studio_options.duration_s = options.duration_s;
  studio_options.xcp = options.xcp;
  boost::asio::io_context io;
  auto studio = studio::Studio::create(io, std::move(studio_options));
  if (!studio) {
    streams.err << "duet studio: " << studio.error() << '\n';
    return ExitCode::failure;
  }
  StopSignals stop;
  if (Status started = studio.value()->start(); !started) {
    streams.err << "duet studio: " << started.error() << '\n';
    return ExitCode::failure;
  }
  streams.out << "duet studio: " << options.model << " on http://" << listen.host << ':' << studio.value()->port()
              << "/ (Ctrl-C stops)" << std::endl;
  serve_until_stopped(io, stop);
  studio.value()->stop();
  streams.out << "duet studio: stopped\n";
  return ExitCode::success;
}

}  // namespace

Action define_studio_command(CLI::App& command) {
  auto options = std::make_shared<StudioCommandOptions>();
  command.add_option("model", options->model, "The model file (docs/MODELS.md)")->required()->check(CLI::ExistingFile);
  command.add_option("--plant", options->plant, "The page's plant: a name, or a plant model's file")
      ->capture_default_str();
  command.add_option("--scenario", options->scenario, "The page's scenario for --plant balbot")
      ->check(CLI::ExistingFile);
  command.add_option("--duration", options->duration_s, "The page's simulation duration in seconds")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 3600.0));
  command
      .add_option("--xcp", options->xcp, "A running target's XCP (tcp://host:port or udp://host:port): external mode")
      ->check(CLI::Validator(
          [](const std::string& text) {
            auto parsed = xcp::host::parse_endpoint(text);
            return parsed ? std::string{} : parsed.error();
          },
          "URI"));
  command.add_option("--listen", options->listen, "Address:port of the page (HTTP and WebSocket)")
      ->capture_default_str()
      ->check(host_port_validator());
  command.add_flag("--expose", options->expose, "Allow listening on addresses other than 127.0.0.1 (the network)");
  command.add_option("--web", options->web, "The built front end (web/dist)")
      ->capture_default_str()
      ->check(CLI::ExistingDirectory);
  return [options](Streams streams) { return run_studio(*options, streams); };
}

}  // namespace duet::cli
