#pragma once
// Which simulated plant a command serves: a name, and for the robot a scenario file and a seed. Shared by
// `duet plant serve` and `duet pil`, so that both make exactly the same plant from the same words.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "duet/plant/balbot/balbot_scenario.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace CLI {  // NOLINT(readability-identifier-naming): CLI11's namespace, declared here only
class App;
}

namespace duet::cli {

struct PlantChoice {
  std::string name;
  std::string scenario;  // a balbot scenario file, or empty
  std::uint64_t seed = 1;
  bool seed_given = false;  // --seed replaces the scenario's seed only when given
};

// Makes a fresh plant each time it is called, so that every session starts alike.
using PlantMaker = std::function<std::unique_ptr<plant::Plant>()>;

struct ChosenPlant {
  PlantMaker make;
  std::optional<plant::BalbotScenario> scenario;  // the robot's scenario when --scenario gave one
};

// Declares --scenario FILE and --seed N on `command`, bound to `choice`.
void add_scenario_and_seed_options(CLI::App& command, PlantChoice& choice);

// Checks the choice once (an unknown plant, a scenario for a plant that takes none, a scenario file that cannot be
// read) and says how to make the plant.
[[nodiscard]] Result<ChosenPlant> choose_plant(const PlantChoice& choice);

// "none, balbot": for help texts.
[[nodiscard]] std::string plant_list();

}  // namespace duet::cli
