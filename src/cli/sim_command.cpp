#include "sim_command.hpp"

#include <CLI/CLI.hpp>

#include <fstream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "checked_model.hpp"
#include "duet/model/model_plant.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/plant.hpp"
#include "duet/plot/figure.hpp"

namespace duet::cli {
namespace {

struct SimOptions {
  std::string file;
  std::string plant = "none";
  double duration_s = 1.0;
  std::vector<std::string> signals;
  std::string csv;
  std::string plot;
  bool no_plot = false;
  std::uint64_t seed = 1;
};

bool write_file(const std::string& path, const std::string& text, Streams streams) {
  std::ofstream file{path};
  file << text;
  if (!file) streams.err << "duet sim: cannot write " << path << '\n';
  return static_cast<bool>(file);
}

ExitCode run_sim(const SimOptions& options, Streams streams) {
  const auto checked = load_checked_model(options.file, streams.err);
  if (!checked) return ExitCode::failure;
  // A plant by name, or a model file that is the plant.
  auto plant = [&]() -> Result<std::unique_ptr<plant::Plant>> {
    if (!options.plant.ends_with(".yaml")) return plant::make_plant(options.plant, options.seed);
    auto loaded = model::ModelPlant::load(options.plant);
    if (!loaded) return Failure{loaded.error()};
    for (const std::string& warning : loaded.value()->warnings()) streams.err << warning << '\n';
    return std::unique_ptr<plant::Plant>{std::move(loaded).value()};
  }();
  if (!plant) {
    streams.err << "duet sim: " << plant.error() << '\n';
    return ExitCode::failure;
  }
  auto simulated = model::simulate(checked->program, *plant.value(), {options.duration_s, options.signals, {}});
  if (!simulated) {
    streams.err << "duet sim: " << simulated.error() << '\n';
    return ExitCode::failure;
  }
  const model::Recording& recording = simulated.value().recording;
  const std::string name = checked->model->name;
  const std::string csv = options.csv.empty() ? name + ".csv" : options.csv;
  if (!write_file(csv, model::to_csv(recording), streams)) return ExitCode::failure;
  streams.out << "simulated " << name << " for " << options.duration_s << " s (" << simulated.value().ticks
              << " base ticks) against plant '" << options.plant << "'; wrote " << csv << " (" << recording.names.size()
              << " columns)";
  if (!options.no_plot) {
    plot::Figure figure{name + " against plant '" + options.plant + "'", "s", recording.time_s, {}};
    for (std::size_t k = 0; k < recording.names.size(); ++k) {
      figure.series.push_back({recording.names[k], recording.units[k], recording.columns[k]});
    }
    const std::string svg = options.plot.empty() ? name + ".svg" : options.plot;
    if (!write_file(svg, plot::to_svg(figure), streams)) return ExitCode::failure;
    streams.out << " and " << svg;
  }
  streams.out << '\n';
  return ExitCode::success;
}

std::string plant_list() {
  std::string text;
  for (const std::string& name : plant::plant_names()) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

Action define_sim_command(CLI::App& command) {
  auto options = std::make_shared<SimOptions>();
  command.add_option("model", options->file, "The model file (docs/MODELS.md)")->required();
  command
      .add_option("--plant", options->plant,
                  "What the model's hardware blocks are connected to: " + plant_list() +
                      ", or a model file (.yaml) whose PlantInput and PlantOutput blocks meet them")
      ->capture_default_str();
  command.add_option("--duration", options->duration_s, "Simulated time in seconds")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  command.add_option("-s,--signal", options->signals,
                     "A signal to record (repeat for more); default: the measurable signals, or all");
  command.add_option("--csv", options->csv, "The CSV file to write (default: the model's name .csv)");
  command.add_option("--plot", options->plot, "The SVG plot to write (default: the model's name .svg)");
  command.add_flag("--no-plot", options->no_plot, "Write no plot");
  command.add_option("--seed", options->seed, "Seed of the plant's noise: the same seed, the same run")
      ->capture_default_str();
  return [options](Streams streams) { return run_sim(*options, streams); };
}

}  // namespace duet::cli
