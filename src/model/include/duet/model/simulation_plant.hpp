#pragma once
// The plant a simulation runs against, as `duet sim` and duet studio name it: a plant by name (plant.hpp), a model
// file that is the plant (model_plant.hpp), or the robot with a scenario file.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::model {

struct SimulationPlant {
  std::unique_ptr<plant::Plant> plant;
  std::vector<std::string> warnings;  // a plant model's own
};

// `plant`: a name, or a path ending in .yaml; `scenario`: a scenario file for `balbot`, or empty; `seed` replaces
// the scenario's or the plant's seed when given.
[[nodiscard]] Result<SimulationPlant> make_simulation_plant(const std::string& plant, const std::string& scenario,
                                                            std::optional<std::uint64_t> seed);

}  // namespace duet::model
