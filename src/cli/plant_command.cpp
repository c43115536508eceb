#include "plant_command.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "duet/link/serve.hpp"
#include "duet/link/tcp.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/plant/balbot/balbot_scenario.hpp"
#include "duet/plant/plant.hpp"
#include "duet/plot/figure.hpp"

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
  std::string csv;   // the plant's observables, a row per TICK, written when a session ends
  std::string plot;  // the same as an SVG plot
};

// A plant that records what the plant behind it shows of itself (Plant::observables) once per TICK, after it
// advanced: the plant's own view of a session, whatever the firmware measures. Without `record` it only passes the
// calls on.
class RecordingPlant : public plant::Plant {
 public:
  RecordingPlant(std::unique_ptr<plant::Plant> behind, bool record)
      : behind_(std::move(behind)), record_(record), observables_(behind_->observables()), now_(observables_.size()) {
    for (const Observable& observable : observables_) {
      recording_.names.push_back(observable.name);
      recording_.units.push_back(observable.unit);
    }
    recording_.columns.resize(observables_.size());
  }

  void advance(double time_s, const plant::RaiseInterrupt& raise) override {
    behind_->advance(time_s, raise);
    if (!record_) return;
    if (recording_.time_s.size() >= most_rows_) {
      truncated_ = true;
      return;
    }
    behind_->observe(now_);
    recording_.time_s.push_back(time_s);
    for (std::size_t k = 0; k < now_.size(); ++k) recording_.columns[k].push_back(now_[k]);
  }
  void write(std::string_view resource, std::span<const double> values) override { behind_->write(resource, values); }
  void read(std::string_view resource, std::span<double> values) override { behind_->read(resource, values); }
  [[nodiscard]] std::vector<Observable> observables() const override { return observables_; }
  void observe(std::span<double> values) const override { behind_->observe(values); }

  [[nodiscard]] const model::Recording& recording() const { return recording_; }
  // Whether the session went on past what is kept in memory (the recording then holds its beginning).
  [[nodiscard]] bool truncated() const { return truncated_; }

 private:
  std::unique_ptr<plant::Plant> behind_;
  bool record_;
  std::vector<Observable> observables_;
  std::vector<double> now_;
  model::Recording recording_;
  // A session in real time may run for hours: keep at most 100 million values (800 MB), as duet sim does.
  std::size_t most_rows_ = 100'000'000 / (observables_.size() + 1);
  bool truncated_ = false;
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

constexpr std::string_view prefix = "duet plant serve: ";

// Whether `path` can be written (it is created, empty): checked before listening rather than after a session.
bool writable(const std::string& path, Streams streams) {
  if (path.empty()) return true;
  const std::ofstream file{path};
  if (!file) streams.err << prefix << "cannot write " << path << '\n';
  return static_cast<bool>(file);
}

bool write_file(const std::string& path, const std::string& text, Streams streams) {
  std::ofstream file{path};
  file << text;
  file.close();
  if (!file) streams.err << prefix << "cannot write " << path << '\n';
  return static_cast<bool>(file);
}

// The session's recording, as --csv and --plot ask.
bool write_recording(const ServeOptions& options, const RecordingPlant& plant, const std::string& peer,
                     Streams streams) {
  const model::Recording& recording = plant.recording();
  if (plant.truncated()) {
    streams.err << prefix << peer << ": the recording holds the first " << recording.time_s.size() << " ticks only\n";
  }
  bool written = true;
  if (!options.csv.empty()) written = write_file(options.csv, model::to_csv(recording), streams) && written;
  if (!options.plot.empty()) {
    plot::Figure figure{"plant " + options.name + ", served to " + peer, "s", recording.time_s, {}};
    for (std::size_t k = 0; k < recording.names.size(); ++k)
      figure.series.push_back({recording.names[k], recording.units[k], recording.columns[k]});
    written = write_file(options.plot, plot::to_svg(figure), streams) && written;
  }
  return written;
}

ExitCode serve_plant(const ServeOptions& options, Streams streams) {
  auto maker = plant_maker(options);
  if (!maker) {
    streams.err << prefix << maker.error() << '\n';
    return ExitCode::failure;
  }
  if (!writable(options.csv, streams) || !writable(options.plot, streams)) return ExitCode::failure;
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
    RecordingPlant plant{maker.value()(), !options.csv.empty() || !options.plot.empty()};
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
  serve
      ->add_option("--csv", options->csv,
                   "Write the plant's own quantities, a row per TICK, to FILE when a session ends (the last session's)")
      ->type_name("FILE");
  serve->add_option("--plot", options->plot, "The same as an SVG plot, a panel per unit")->type_name("FILE");
  return [options](Streams streams) { return serve_plant(*options, streams); };
}

}  // namespace duet::cli
