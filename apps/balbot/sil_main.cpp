// balbot_sil: the robot's generated firmware built for the PC, in the loop with the simulated robot (README.md,
// "Software in the loop over the link"). Its hardware is the robot that `duet plant serve balbot` serves over TCP
// (--link), or the simulated robot in this process (--plant balbot), for benchmarks and comparisons.
//
//   balbot_sil [--link HOST:PORT | --plant NAME [--scenario FILE] [--seed N]] [--duration S] [--real-time]
//              [--csv FILE] [--xcp HOST:PORT]
//
// --xcp serves the firmware's XCP slave on TCP (sil_xcp.hpp), for duet xcp, duet monitor and duet studio; its line
// "balbot_sil: XCP on tcp://HOST:PORT" comes before the run starts.
//
// It ends with one line: the ticks run, the final tilt and the largest |tilt| after 4 s, numbers written so that they
// read back as the same doubles. Exit codes: 0 the run went through, 1 it failed (a link, a plant, a file), 2 the
// command line is wrong.

#include <CLI/CLI.hpp>

#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "balbot.hpp"
#include "duet/link/pacer.hpp"
#include "duet/link/remote_plant.hpp"
#include "duet/link/tcp.hpp"
#include "duet/model/data_type.hpp"
#include "duet/model/simulation.hpp"
#include "duet/model/simulation_plant.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/number_text.hpp"
#include "sil_run.hpp"
#include "sil_xcp.hpp"

namespace {

namespace link = duet::link;
namespace plant = duet::plant;
namespace sil = duet::sil;

constexpr int success = 0;
constexpr int failure = 1;
constexpr int usage = 2;

struct Options {
  std::string link = "127.0.0.1:" + std::to_string(link::default_port);
  std::string plant;  // none: over the link
  std::string scenario;
  std::optional<std::uint64_t> seed;
  double duration_s = 10;
  bool real_time = false;
  std::string csv;
  std::string xcp;  // HOST:PORT, or none
};

int fail(const std::string& message) {
  std::cerr << "balbot_sil: " << message << '\n';
  return failure;
}

std::string summary(const Options& options, const sil::SilResult& result, std::uint64_t late_ticks) {
  using duet::shortest_text;
  std::string text = "balbot_sil: " + std::to_string(result.ticks) + " ticks (" +
                     (options.real_time ? "real time, " + std::to_string(late_ticks) + " late" : "lock-step") + ", " +
                     (options.plant.empty() ? "plant at " + options.link : "plant " + options.plant + " in process") +
                     "); final theta " + shortest_text(result.final_theta_deg) + " deg; largest |theta| after 4 s ";
  text += result.largest_theta_after_4_s_deg ? shortest_text(*result.largest_theta_after_4_s_deg) + " deg" : "none";
  if (!options.csv.empty()) text += "; wrote " + options.csv;
  return text;
}

int run(const Options& options) {
  std::optional<sil::Measurements> measurements;
  std::ofstream csv;
  if (!options.csv.empty()) {
    auto loaded = sil::balbot_measurements();
    if (!loaded) return fail(loaded.error());
    measurements = std::move(loaded).value();
    csv.open(options.csv);  // now, so that a file that cannot be written fails before the run
    if (!csv) return fail("cannot write " + options.csv);
  }
  sil::SilOptions run_options{.duration_s = options.duration_s,
                              .measurements = measurements ? &*measurements : nullptr};
  link::Pacer pacer;
  std::unique_ptr<plant::Plant> plant;
  link::RemotePlant* remote = nullptr;
  if (options.plant.empty()) {
    auto address = link::parse_host_port(options.link);  // checked by the option's validator already
    if (!address) return fail(address.error());
    auto stream = link::connect_tcp(address.value());
    if (!stream) return fail(stream.error() + " (is 'duet plant serve balbot' running?)");
    const link::LinkMode mode = options.real_time ? link::LinkMode::real_time : link::LinkMode::lock_step;
    auto connected = link::RemotePlant::connect(std::move(stream).value(), {mode, balbot::description.base_period_ns});
    if (!connected) return fail(connected.error());
    remote = connected.value().get();
    plant = std::move(connected).value();
    run_options.check = [remote] { return remote->status(); };
  } else {
    auto made = duet::model::make_simulation_plant(options.plant, options.scenario, options.seed);
    if (!made) return fail(made.error());
    plant = std::move(made).value().plant;
    if (options.real_time) run_options.pacer = &pacer;
  }

  sil::SilXcp xcp;
  if (!options.xcp.empty()) {
    auto address = link::parse_host_port(options.xcp);  // checked by the option's validator already
    if (!address) return fail(address.error());
    if (auto started = xcp.start(address.value().host, address.value().port); !started) return fail(started.error());
    run_options.memory_lock = &xcp.memory_lock();
    run_options.tick_started = [&xcp](double now_s) { xcp.tick_started(now_s); };
    run_options.task_finished = [&xcp](std::size_t task) { xcp.task_finished(task); };
    std::cout << "balbot_sil: XCP on tcp://" << address.value().host << ':' << xcp.port() << std::endl;
  }
  auto result = sil::run_sil(*plant, run_options);
  if (!result) return fail(result.error());
  if (remote != nullptr) {
    if (auto closed = remote->close(); !closed) return fail(closed.error());
  }
  if (csv.is_open()) {
    csv << duet::model::to_csv(result.value().recording);
    csv.close();
    if (!csv) return fail("cannot write " + options.csv);
  }
  const std::uint64_t late = remote != nullptr ? remote->pacer().late() : pacer.late();
  std::cout << summary(options, result.value(), late) << '\n';
  return success;
}

CLI::Validator host_port() {
  return CLI::Validator(
      [](const std::string& text) {
        auto parsed = link::parse_host_port(text);
        return parsed ? std::string{} : parsed.error();
      },
      "");
}

int parse_and_run(int argc, char** argv) {
  Options options;
  CLI::App app{"The robot's generated firmware on the PC, in the loop with the simulated robot", "balbot_sil"};
  app.footer("Exit codes: 0 success, 1 the run failed, 2 the command line is wrong.");
  auto* link_option = app.add_option("--link", options.link, "HOST:PORT where 'duet plant serve balbot' listens")
                          ->capture_default_str()
                          ->type_name("HOST:PORT")
                          ->check(host_port());
  auto* plant_option =
      app.add_option("--plant", options.plant, "The simulated plant in this process instead of the link (balbot)")
          ->type_name("NAME")
          ->excludes(link_option);
  app.add_option("--scenario", options.scenario, "With --plant balbot: the scenario file (src/plant/balbot/README.md)")
      ->type_name("FILE")
      ->needs(plant_option);
  app.add_option_function<std::uint64_t>(
         "--seed", [&options](const std::uint64_t& seed) { options.seed = seed; },
         "With --plant: the seed of the robot's noise (replaces the scenario's)")
      ->type_name("UINT")
      ->needs(plant_option);
  app.add_option("--duration", options.duration_s, "Simulated time in seconds")
      ->capture_default_str()
      ->type_name("S")
      ->check(CLI::Range(0.0, 1e6));
  app.add_flag("--real-time", options.real_time, "Pace the ticks with the wall clock (default: lock-step, at once)");
  app.add_option("--csv", options.csv, "Write the firmware's measurable signals, a row per tick, to FILE")
      ->type_name("FILE");
  app.add_option("--xcp", options.xcp, "Serve the firmware's XCP slave on TCP at HOST:PORT (port 0: any free port)")
      ->type_name("HOST:PORT")
      ->check(host_port());
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "balbot_sil: " << error.what() << ". See 'balbot_sil --help'.\n";
    return usage;
  }
  return run(options);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return parse_and_run(argc, argv);
  } catch (const std::exception& error) {  // a bug or an exhausted machine: say so instead of aborting
    std::cerr << "balbot_sil: internal error: " << error.what() << '\n';
    return failure;
  }
}
