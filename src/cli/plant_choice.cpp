#include "plant_choice.hpp"

#include <CLI/CLI.hpp>

#include "duet/plant/balbot/balbot_plant.hpp"

namespace duet::cli {

void add_scenario_and_seed_options(CLI::App& command, PlantChoice& choice) {
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
}

Result<ChosenPlant> choose_plant(const PlantChoice& choice) {
  if (!choice.scenario.empty()) {
    if (choice.name != "balbot") {
      return Failure{"--scenario is for the balbot plant; plant '" + choice.name + "' takes none"};
    }
    auto scenario = plant::load_balbot_scenario(choice.scenario);
    if (!scenario) return Failure{scenario.error()};
    plant::BalbotScenario chosen = std::move(scenario).value();
    if (choice.seed_given) chosen.seed = choice.seed;
    return ChosenPlant{[chosen] { return std::unique_ptr<plant::Plant>{plant::make_balbot_plant(chosen)}; }, chosen};
  }
  auto made = plant::make_plant(choice.name, choice.seed);
  if (!made) return Failure{made.error()};
  return ChosenPlant{[name = choice.name, seed = choice.seed] {
                       auto plant = plant::make_plant(name, seed);
                       return plant ? std::move(plant).value() : nullptr;
                     },
                     std::nullopt};
}

std::string plant_list() {
  std::string text;
  for (const std::string& name : plant::plant_names()) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace duet::cli
