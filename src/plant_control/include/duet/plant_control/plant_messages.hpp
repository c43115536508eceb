#pragma once
// The plant-control protocol's messages (docs/LINK.md, "Plant control"): JSON objects, one per line. What a plant
// offers as a `description`; a `plant` request read into a Disturbance; its answer, applied with the model time or
// refused with the problem.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "duet/plant/plant_controls.hpp"
#include "duet/support/result.hpp"

namespace duet::plant_control {

// {"type": "description", "plant": NAME, "actions": [{name, summary, arguments: [{name, unit, min, max, default}]}]}
[[nodiscard]] nlohmann::json description_message(const std::string& plant,
                                                 const std::vector<plant::DisturbanceKind>& offered);

// {"type": "plant", "action": "push", "force_n": 5, "duration_s": 0.05}: the action's arguments by name, each a
// number; one left out takes its default. Fails naming the problem: no action, an unknown one (with the known ones),
// an argument it does not take, one that is not a number. Limits are PlantControls' to check.
[[nodiscard]] Result<plant::Disturbance> read_request(const nlohmann::json& request,
                                                      const std::vector<plant::DisturbanceKind>& offered);

// {"type": "plant", "action": "push", "arguments": {"force_n": 5, "duration_s": 0.05}, "time_s": 12.345}
[[nodiscard]] nlohmann::json applied_message(const plant::AppliedDisturbance& applied,
                                             const std::vector<plant::DisturbanceKind>& offered);
// {"type": "plant", "action": ACTION, "error": PROBLEM} (no action member when the request named none)
[[nodiscard]] nlohmann::json refused_message(const nlohmann::json& request, const std::string& problem);

}  // namespace duet::plant_control
