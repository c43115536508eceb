#include "duet/model/simulation_plant.hpp"

#include "duet/model/model_plant.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/plant/balbot/balbot_scenario.hpp"

namespace duet::model {

Result<SimulationPlant> make_simulation_plant(const std::string& plant, const std::string& scenario,
                                              std::optional<std::uint64_t> seed) {
  if (!scenario.empty()) {
    if (plant != "balbot") return Failure{"--scenario is for --plant balbot"};
    auto loaded = plant::load_balbot_scenario(scenario);
    if (!loaded) return Failure{loaded.error()};
    if (seed) loaded.value().seed = *seed;
    return SimulationPlant{std::unique_ptr<plant::Plant>{plant::make_balbot_plant(loaded.value())}, {}};
  }
  if (!plant.ends_with(".yaml")) {
    auto made = plant::make_plant(plant, seed.value_or(1));
    if (!made) return Failure{made.error()};
    return SimulationPlant{std::move(made).value(), {}};
  }
  auto loaded = ModelPlant::load(plant);
  if (!loaded) return Failure{loaded.error()};
  std::vector<std::string> warnings = loaded.value()->warnings();
  return SimulationPlant{std::unique_ptr<plant::Plant>{std::move(loaded).value()}, std::move(warnings)};
}

}  // namespace duet::model
