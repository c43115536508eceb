#include "duet/plant_control/plant_messages.hpp"

#include <algorithm>

namespace duet::plant_control {

using nlohmann::json;

namespace {

// Members of a request that are not the action's arguments.
bool is_envelope(const std::string& member) { return member == "type" || member == "action" || member == "id"; }

const plant::DisturbanceKind* kind_named(const std::vector<plant::DisturbanceKind>& offered, const std::string& name) {
  const auto found = std::find_if(offered.begin(), offered.end(),
                                  [&name](const plant::DisturbanceKind& kind) { return kind.name == name; });
  return found == offered.end() ? nullptr : &*found;
}

std::string names_of(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

}  // namespace

json description_message(const std::string& plant, const std::vector<plant::DisturbanceKind>& offered) {
  json actions = json::array();
  for (const plant::DisturbanceKind& kind : offered) {
    json arguments = json::array();
    for (const plant::DisturbanceArgument& argument : kind.arguments) {
      arguments.push_back({{"name", argument.name},
                           {"unit", argument.unit},
                           {"min", argument.minimum},
                           {"max", argument.maximum},
                           {"default", argument.default_value}});
    }
    actions.push_back({{"name", kind.name}, {"summary", kind.summary}, {"arguments", arguments}});
  }
  return {{"type", "description"}, {"plant", plant}, {"actions", actions}};
}

Result<plant::Disturbance> read_request(const json& request, const std::vector<plant::DisturbanceKind>& offered) {
  std::vector<std::string> known;
  known.reserve(offered.size());
  for (const plant::DisturbanceKind& kind : offered) known.push_back(kind.name);
  if (!request.contains("action") || !request["action"].is_string()) {
    return Failure{"a plant request needs \"action\": " + names_of(known)};
  }
  const std::string name = request["action"].get<std::string>();
  const plant::DisturbanceKind* kind = kind_named(offered, name);
  if (kind == nullptr) return Failure{"unknown action '" + name + "': " + names_of(known)};
  std::vector<std::string> takes;
  takes.reserve(kind->arguments.size());
  for (const plant::DisturbanceArgument& argument : kind->arguments) takes.push_back(argument.name);
  for (const auto& [member, value] : request.items()) {
    if (!is_envelope(member) && std::find(takes.begin(), takes.end(), member) == takes.end()) {
      std::string problem = name + " takes no argument '";
      problem += member;
      problem += takes.empty() ? "' (it takes none)" : "' (" + names_of(takes) + ")";
      return Failure{problem};
    }
  }
  plant::Disturbance disturbance{name, {}};
  for (const plant::DisturbanceArgument& argument : kind->arguments) {
    if (!request.contains(argument.name)) {
      disturbance.arguments.push_back(argument.default_value);
    } else if (request[argument.name].is_number()) {
      disturbance.arguments.push_back(request[argument.name].get<double>());
    } else {
      return Failure{name + ": " + argument.name + " is a number" +
                     (argument.unit.empty() ? std::string{} : " (" + argument.unit + ")")};
    }
  }
  return disturbance;
}

json applied_message(const plant::AppliedDisturbance& applied, const std::vector<plant::DisturbanceKind>& offered) {
  json arguments = json::object();
  if (const plant::DisturbanceKind* kind = kind_named(offered, applied.disturbance.name)) {
    for (std::size_t k = 0; k < kind->arguments.size() && k < applied.disturbance.arguments.size(); ++k) {
      arguments[kind->arguments[k].name] = applied.disturbance.arguments[k];
    }
  }
  return {
      {"type", "plant"}, {"action", applied.disturbance.name}, {"arguments", arguments}, {"time_s", applied.time_s}};
}

json refused_message(const json& request, const std::string& problem) {
  json message = {{"type", "plant"}, {"error", problem}};
  if (request.is_object() && request.contains("action") && request["action"].is_string()) {
    message["action"] = request["action"];
  }
  return message;
}

}  // namespace duet::plant_control
