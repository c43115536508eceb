#include "plant_control_endpoint.hpp"

#include "duet/link/tcp.hpp"

namespace duet::cli {

Result<PlantControlEndpoint> PlantControlEndpoint::open(const ChosenPlant& chosen, const std::string& plant_name,
                                                        const std::string& address) {
  PlantControlEndpoint endpoint;
  auto probe = chosen.make();
  if (!probe) return Failure{probe.error()};
  std::vector<plant::DisturbanceKind> offered = probe.value()->disturbances();
  if (offered.empty()) return endpoint;
  auto host_port = link::parse_host_port(address);
  if (!host_port) return Failure{"--plant-control " + host_port.error()};
  endpoint.controls_ = std::make_unique<plant::PlantControls>(std::move(offered));
  auto server = plant_control::PlantControlServer::start(
      *endpoint.controls_, {.host = host_port.value().host, .port = host_port.value().port, .plant = plant_name});
  if (!server) return Failure{server.error()};
  endpoint.server_ = std::move(server).value();
  return endpoint;
}

std::string PlantControlEndpoint::actions() const {
  std::string names;
  for (const plant::DisturbanceKind& kind : offered()) names += (names.empty() ? "" : ", ") + kind.name;
  return names;
}

std::unique_ptr<plant::Plant> PlantControlEndpoint::controlled(std::unique_ptr<plant::Plant> plant) {
  if (!controls_) return plant;
  return std::make_unique<plant::ControlledPlant>(std::move(plant), *controls_);
}

std::vector<plant::AppliedDisturbance> PlantControlEndpoint::applied() const {
  return controls_ ? controls_->applied() : std::vector<plant::AppliedDisturbance>{};
}

std::vector<plant::DisturbanceKind> PlantControlEndpoint::offered() const {
  return controls_ ? controls_->offered() : std::vector<plant::DisturbanceKind>{};
}

}  // namespace duet::cli
