#include "duet/plant/plant.hpp"

#include <algorithm>
#include <array>

#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/support/closest_word.hpp"

namespace duet::plant {

void Loopback::advance(double, const RaiseInterrupt&) {}

void Loopback::write(std::string_view resource, std::span<const double> values) {
  ++writes_;
  for (auto& [name, held] : values_) {
    if (name == resource) {
      held.assign(values.begin(), values.end());
      return;
    }
  }
  values_.emplace_back(std::string{resource}, std::vector<double>(values.begin(), values.end()));
}

void Loopback::read(std::string_view resource, std::span<double> values) {
  std::fill(values.begin(), values.end(), 0.0);
  const std::vector<double> held = value(resource);
  std::copy_n(held.begin(), std::min(held.size(), values.size()), values.begin());
}

std::vector<double> Loopback::value(std::string_view resource) const {
  for (const auto& [name, held] : values_) {
    if (name == resource) return held;
  }
  return {};
}

namespace {

// The plants by name: one line each.
struct NamedPlant {
  std::string_view name;
  std::unique_ptr<Plant> (*make)(std::uint64_t seed);
};
constexpr std::array<NamedPlant, 2> plants{{
    {"none", [](std::uint64_t) -> std::unique_ptr<Plant> { return std::make_unique<Loopback>(); }},
    {"balbot", [](std::uint64_t seed) -> std::unique_ptr<Plant> { return make_balbot_plant(seed); }},
}};

}  // namespace

std::vector<std::string> plant_names() {
  std::vector<std::string> names;
  names.reserve(plants.size());
  for (const NamedPlant& plant : plants) names.emplace_back(plant.name);
  return names;
}

Result<std::unique_ptr<Plant>> make_plant(std::string_view name, std::uint64_t seed) {
  for (const NamedPlant& plant : plants) {
    if (plant.name == name) return plant.make(seed);
  }
  const std::vector<std::string> names = plant_names();
  const std::vector<std::string_view> views(names.begin(), names.end());
  const auto closest = closest_word(name, views);
  std::string known;
  for (const std::string& known_name : names) known += (known.empty() ? "" : ", ") + known_name;
  return Failure{"unknown plant '" + std::string{name} + "'" +
                 (closest ? " (did you mean '" + std::string{*closest} + "'?)" : " (known: " + known + ")")};
}

}  // namespace duet::plant
