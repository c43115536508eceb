#include "plant_command.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

#include "duet/link/serve.hpp"
#include "duet/link/tcp.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/plant/balbot/balbot_scenario.hpp"
#include "duet/plant/plant.hpp"

namespace duet::cli {
namespace {

struct ServeOptions {
  std::string name;
  std::string scenario;
  std::uint64_t seed = 1;
  bool seed_given = false;
  std::string listen = "127.0.0.1:" + std::to_string(link::default_port);
  bool once = false;
  double timeout_s = 10;
};

using PlantMaker = std::function<std::unique_ptr<plant::Plant>()>;

// How each connection gets a fresh plant, so that every run starts alike; checked once before listening.
Result<PlantMaker> plant_maker(const ServeOptions& options) {
  if (!options.scenario.empty()) {
    if (options.name != "balbot") {
      return Failure{"--scenario is for the balbot plant; plant '" + options.name + "' takes none"};
    }
    auto scenario = plant::load_balbot_scenario(options.scenario);
    if (!scenario) return Failure{scenario.error()};
    plant::BalbotScenario chosen = std::move(scenario).value();
    if (options.seed_given) chosen.seed = options.seed;
    return PlantMaker{[chosen] { return std::unique_ptr<plant::Plant>{plant::make_balbot_plant(chosen)}; }};
  }
  auto made = plant::make_plant(options.name, options.seed);
  if (!made) return Failure{made.error()};
  return PlantMaker{[name = options.name, seed = options.seed] {
    auto plant = plant::make_plant(name, seed);
    return plant ? std::move(plant).value() : nullptr;
  }};
}

std::string describe(const link::ServeSummary& summary) {
  const bool lock_step = summary.hello.mode == link::LinkMode::lock_step;
  return std::to_string(summary.ticks) + " ticks, " + std::to_string(summary.interrupts) + " interrupts, " +
         std::to_string(summary.writes) + " writes, " + std::to_string(summary.reads) + " reads (" +
         (lock_step ? "lock-step" : "real time") + ", base period " +
         std::to_string(summary.hello.base_period_ns / 1000) + " us)" + (summary.said_bye ? "" : ", ended without BYE");
}

ExitCode serve_plant(const ServeOptions& options, Streams streams) {
  constexpr std::string_view prefix = "duet plant serve: ";
  auto maker = plant_maker(options);
  if (!maker) {
    streams.err << prefix << maker.error() << '\n';
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
  const link::Timeout session_timeout =
      options.timeout_s == 0 ? link::no_timeout
                             : link::Timeout{static_cast<link::Timeout::rep>(std::ceil(options.timeout_s * 1000))};
  streams.out << "plant " << options.name << " listening on " << link::to_string(listener.value().address())
              << std::endl;  // a line scripts wait for: flushed now
  for (;;) {
    auto accepted = listener.value().accept(link::no_timeout, session_timeout);
    if (!accepted) {
      streams.err << prefix << accepted.error() << '\n';
      return ExitCode::failure;
    }
    const std::unique_ptr<plant::Plant> plant = maker.value()();
    auto served = link::serve(*plant, *accepted.value().stream);
    if (served) {
      streams.out << "served " << accepted.value().peer << ": " << describe(served.value()) << std::endl;
    } else {
      streams.err << prefix << accepted.value().peer << ": " << served.error() << std::endl;
    }
    if (options.once) return served ? ExitCode::success : ExitCode::failure;
  }
}

std::string plant_list() {
  std::string text;
  for (const std::string& name : plant::plant_names()) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

Action define_plant_command(CLI::App& command) {
  auto options = std::make_shared<ServeOptions>();
  command.require_subcommand(1);
  CLI::App* serve = command.add_subcommand(
      "serve", "Serve a simulated plant over the virtual-hardware link to firmware that connects over TCP");
  serve->add_option("name", options->name, "The plant: " + plant_list())->required()->type_name("NAME");
  serve->add_option("--scenario", options->scenario, "balbot: the scenario file (YAML, src/plant/balbot/README.md)")
      ->type_name("FILE");
  serve
      ->add_option_function<std::uint64_t>(
          "--seed",
          [options](const std::uint64_t& seed) {
            options->seed = seed;
            options->seed_given = true;
          },
          "Seed of the plant's noise: the same seed, the same run (default 1, or the scenario's)")
      ->type_name("UINT");
  serve
      ->add_option("--listen", options->listen,
                   "HOST:PORT to listen on; port 0 takes a free port (the line printed says which)")
      ->capture_default_str()
      ->type_name("HOST:PORT")
      ->check(CLI::Validator(
          [](const std::string& text) {
            auto parsed = link::parse_host_port(text);
            return parsed ? std::string{} : parsed.error();
          },
          ""));
  serve->add_flag("--once", options->once, "Serve one firmware, then exit (with 1 if that session failed)");
  serve
      ->add_option("--timeout", options->timeout_s,
                   "Seconds to wait for the firmware's next frame before giving up on it (0: forever)")
      ->capture_default_str()
      ->type_name("S")
      ->check(CLI::Range(0.0, 1e6));
  return [options](Streams streams) { return serve_plant(*options, streams); };
}

}  // namespace duet::cli
