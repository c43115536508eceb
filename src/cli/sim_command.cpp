#include "sim_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "checked_model.hpp"
#include "duet/mdf4_recording/recording_file.hpp"
#include "duet/model/data_type.hpp"
#include "duet/model/interpreter.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/plant.hpp"
#include "duet/plot/figure.hpp"
#include "duet/support/number_text.hpp"
#include "plant_choice.hpp"

namespace duet::cli {
namespace {

struct SimOptions {
  std::string file;
  PlantChoice plant{.name = "none"};
  double duration_s = 1.0;
  std::vector<std::string> signals;
  std::string csv;
  std::string plot;
  std::string mdf;
  bool no_plot = false;
  std::vector<std::string> settings;  // NAME=VALUE or NAME=V1,V2,...
};

// A parameter's new value from the command line, as the model's parameter number and its elements.
struct Setting {
  std::size_t parameter = 0;
  std::vector<double> values;
};

Result<std::vector<Setting>> parse_settings(const model::Model& model, const std::vector<std::string>& settings) {
  std::vector<Setting> result;
  for (const std::string& text : settings) {
    const std::size_t equals = text.find('=');
    const std::string name = text.substr(0, equals);
    const auto found = std::find_if(model.parameters.begin(), model.parameters.end(),
                                    [&name](const model::Parameter& parameter) { return parameter.name == name; });
    if (equals == std::string::npos || found == model.parameters.end()) {
      return Failure{"--parameter '" + text + "': " +
                     (equals == std::string::npos ? std::string{"write NAME=VALUE"}
                                                  : "the model has no parameter '" + name + "'")};
    }
    Setting setting{static_cast<std::size_t>(found - model.parameters.begin()), {}};
    std::stringstream values{text.substr(equals + 1)};
    for (std::string item; std::getline(values, item, ',');) {
      std::size_t used = 0;
      double value = 0;
      try {
        value = std::stod(item, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != item.size())
        return Failure{"--parameter '" + text + "': '" + item + "' is not a number"};
      setting.values.push_back(value);
    }
    const std::size_t elements = found->value.elements.size();
    if (setting.values.size() != 1 && setting.values.size() != elements) {
      return Failure{"--parameter '" + text + "': '" + name + "' has " + std::to_string(elements) +
                     " elements: give one value for all, or one each"};
    }
    setting.values.resize(elements, setting.values.front());
    result.push_back(std::move(setting));
  }
  return result;
}

bool write_file(const std::string& path, const std::string& text, Streams streams) {
  std::ofstream file{path};
  file << text;
  if (!file) streams.err << "duet sim: cannot write " << path << '\n';
  return static_cast<bool>(file);
}

ExitCode run_sim(const SimOptions& options, Streams streams) {
  const auto checked = load_checked_model(options.file, streams.err);
  if (!checked) return ExitCode::failure;
  auto chosen = choose_plant(options.plant, log_lines_to(streams.err));
  auto plant = chosen ? chosen.value().make() : Failure{chosen.error()};
  if (!plant) {
    streams.err << "duet sim: " << plant.error() << '\n';
    return ExitCode::failure;
  }
  auto settings = parse_settings(*checked->model, options.settings);
  if (!settings) {
    streams.err << "duet sim: " << settings.error() << '\n';
    return ExitCode::failure;
  }
  model::SimulationOptions simulation{options.duration_s, options.signals, {}};
  simulation.before_tick = [&settings](std::uint64_t tick, model::Interpreter& model) {
    if (tick != 0) return;
    for (const Setting& setting : settings.value()) {
      for (std::size_t k = 0; k < setting.values.size(); ++k)
        model.set_parameter(setting.parameter, k, setting.values[k]);
    }
  };
  auto simulated = model::simulate(checked->program, *plant.value(), simulation);
  if (!simulated) {
    streams.err << "duet sim: " << simulated.error() << '\n';
    return ExitCode::failure;
  }
  if (!simulated.value().plant_stop.empty())
    streams.err << "duet sim: the plant ended the run: " << simulated.value().plant_stop << '\n';
  const model::Recording& recording = simulated.value().recording;
  const std::string name = checked->model->name;
  // With --mdf and no --csv, the MDF file is the recording.
  const std::string csv = !options.csv.empty() ? options.csv : options.mdf.empty() ? name + ".csv" : std::string{};
  if (!csv.empty() && !write_file(csv, model::to_csv(recording), streams)) return ExitCode::failure;
  if (!options.mdf.empty()) {
    const auto now = std::chrono::system_clock::now().time_since_epoch();
    const std::string group = "base period " + shortest_text(checked->model->base_period_us) + " us";
    const Status written = mdf4_recording::write_recording_file(
        options.mdf, recording,
        {.group = group,
         .comment = "duet sim " + options.file + " against plant '" + options.plant.name + "'",
         .start_time_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(now).count(),
         .program = &checked->program});
    if (!written) {
      streams.err << "duet sim: " << written.error() << '\n';
      return ExitCode::failure;
    }
  }
  const double simulated_s = recording.time_s.empty() ? 0.0 : recording.time_s.back();
  streams.out << "simulated " << name << " for "
              << (simulated.value().plant_stop.empty() ? options.duration_s : simulated_s) << " s ("
              << simulated.value().ticks << " base ticks) against plant '" << options.plant.name << "'; wrote "
              << (csv.empty() || options.mdf.empty() ? csv + options.mdf : csv + " and " + options.mdf) << " ("
              << recording.names.size() << " columns)";
  if (!options.no_plot) {
    plot::Figure figure{name + " against plant '" + options.plant.name + "'", "s", recording.time_s, {}};
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

}  // namespace

Action define_sim_command(CLI::App& command) {
  auto options = std::make_shared<SimOptions>();
  command.add_option("model", options->file, "The model file (docs/MODELS.md)")->required();
  command
      .add_option("--plant", options->plant.name,
                  "What the model's hardware blocks are connected to: " + plant_list() +
                      "; a plant model's PlantInput and PlantOutput blocks meet them by name")
      ->capture_default_str();
  command.add_option("--duration", options->duration_s, "Simulated time in seconds")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e6));
  command.add_option("-s,--signal", options->signals,
                     "A signal to record (repeat for more); default: the measurable signals, or all");
  command.add_option("--csv", options->csv, "The CSV file to write (default: the model's name .csv, unless --mdf)");
  command.add_option("--mdf", options->mdf, "Also (or instead of CSV) an MDF 4 file, the signals in their types");
  command.add_option("--plot", options->plot, "The SVG plot to write (default: the model's name .svg)");
  command.add_flag("--no-plot", options->no_plot, "Write no plot");
  command.add_option(
      "-p,--parameter", options->settings,
      "Tune a parameter from the start: NAME=VALUE, or NAME=V1,V2,... one per element (repeat for more)");
  add_plant_options(command, options->plant);
  return [options](Streams streams) {
    if (auto misuse = plant_options_misuse(options->plant)) {
      streams.err << "duet sim: " << *misuse << '\n';
      return ExitCode::usage;
    }
    return run_sim(*options, streams);
  };
}

}  // namespace duet::cli
