#include "plant_choice.hpp"

#include <CLI/CLI.hpp>

#include <mutex>
#include <ostream>

#include "duet/fmu_plant/fmu_plant.hpp"
#include "duet/model/simulation_plant.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"

namespace duet::cli {
namespace {

bool is_fmu(const PlantChoice& choice) { return choice.name.ends_with(".fmu"); }

// The FMU with its mapping, read once; each plant made opens the FMU afresh (its own folder and instance).
Result<ChosenPlant> choose_fmu(const PlantChoice& choice, const PlantLog& log) {
  auto mapping = fmu_plant::read_fmu_mapping(choice.connect);
  if (!mapping) return Failure{mapping.error()};
  for (const std::string& setting : choice.fmu_settings) {
    if (auto added = fmu_plant::add_setting(mapping.value(), setting); !added) return Failure{added.error()};
  }
  PlantMaker make = [fmu = choice.name, mapping = std::move(mapping).value(),
                     log]() -> Result<std::unique_ptr<plant::Plant>> {
    auto loaded = fmu_plant::FmuPlant::load({.fmu = fmu, .mapping = mapping, .log = log});
    if (!loaded) return Failure{loaded.error()};
    return std::unique_ptr<plant::Plant>{std::move(loaded).value()};
  };
  if (auto checked = make(); !checked) return Failure{checked.error()};
  return ChosenPlant{std::move(make), std::nullopt};
}

}  // namespace

PlantLog log_lines_to(std::ostream& out) {
  return [&out, mutex = std::make_shared<std::mutex>()](std::string_view line) {
    const std::scoped_lock lock{*mutex};
    out << line << '\n' << std::flush;
  };
}

void add_plant_options(CLI::App& command, PlantChoice& choice) {
  command.add_option("--scenario", choice.scenario, "balbot: the scenario file (YAML, src/plant/balbot/README.md)")
      ->type_name("FILE");
  command
      .add_option_function<std::uint64_t>(
          "--seed",
          [&choice](const std::uint64_t& seed) {
            choice.seed = seed;
            choice.seed_given = true;
          },
          "Seed of the plant's noise: the same seed, the same run (default 1, or the scenario's)")
      ->type_name("UINT");
  command
      .add_option("--connect", choice.connect,
                  "With an FMU as the plant: the mapping file (YAML) of its variables to the model's resources "
                  "(docs/FMI.md)")
      ->type_name("FILE");
  command
      .add_option("--fmu-set", choice.fmu_settings,
                  "With an FMU as the plant: a parameter or start value, NAME=VALUE (repeat for more)")
      ->type_name("NAME=VALUE");
}

std::optional<std::string> plant_options_misuse(const PlantChoice& choice) {
  if (is_fmu(choice) && choice.connect.empty()) return "an FMU as the plant needs --connect MAPPING.yaml";
  if (!is_fmu(choice) && (!choice.connect.empty() || !choice.fmu_settings.empty()))
    return "--connect and --fmu-set are for an FMU as the plant (X.fmu)";
  return std::nullopt;
}

Result<ChosenPlant> choose_plant(const PlantChoice& choice, const PlantLog& log) {
  if (auto misuse = plant_options_misuse(choice)) return Failure{*misuse};
  if (is_fmu(choice)) return choose_fmu(choice, log);
  if (!choice.scenario.empty()) {
    if (choice.name != "balbot") {
      return Failure{"--scenario is for the balbot plant; plant '" + choice.name + "' takes none"};
    }
    auto scenario = plant::load_balbot_scenario(choice.scenario);
    if (!scenario) return Failure{scenario.error()};
    plant::BalbotScenario chosen = std::move(scenario).value();
    if (choice.seed_given) chosen.seed = choice.seed;
    return ChosenPlant{[chosen]() -> Result<std::unique_ptr<plant::Plant>> {
                         return std::unique_ptr<plant::Plant>{plant::make_balbot_plant(chosen)};
                       },
                       chosen};
  }
  // A plant by name, or a plant model, whose warnings are said once.
  const auto make = [name = choice.name, seed = choice.seed](std::vector<std::string>* warnings) {
    auto made = model::make_simulation_plant(name, "", seed);
    if (!made) return Result<std::unique_ptr<plant::Plant>>{Failure{made.error()}};
    if (warnings != nullptr) *warnings = std::move(made.value().warnings);
    return Result<std::unique_ptr<plant::Plant>>{std::move(made.value().plant)};
  };
  std::vector<std::string> warnings;
  if (auto checked = make(&warnings); !checked) return Failure{checked.error()};
  for (const std::string& warning : warnings) log(warning);
  return ChosenPlant{[make] { return make(nullptr); }, std::nullopt};
}

std::string plant_list() {
  std::string text;
  for (const std::string& name : plant::plant_names()) text += name + ", ";
  return text + "a plant model (.yaml) or a co-simulation FMU (.fmu) with --connect";
}

}  // namespace duet::cli
