#pragma once
// The plant-control endpoint a command that serves a plant offers (`duet plant serve`, `duet pil`; docs/LINK.md,
// "Plant control"): opened when the chosen plant offers disturbances, on this machine only.

#include <memory>
#include <string>

#include "duet/plant/plant_controls.hpp"
#include "duet/plant_control/plant_control_server.hpp"
#include "duet/support/result.hpp"
#include "plant_choice.hpp"

namespace duet::cli {

class PlantControlEndpoint {
 public:
  // Listens on `address` (HOST:PORT, port 0: a free one) when the plant `chosen` makes offers disturbances; else
  // there is no endpoint. Fails naming the address.
  [[nodiscard]] static Result<PlantControlEndpoint> open(const ChosenPlant& chosen, const std::string& plant_name,
                                                         const std::string& address);

  // Where it listens ("127.0.0.1:40312"), or empty without an endpoint.
  [[nodiscard]] std::string address() const { return server_ ? server_->address() : std::string{}; }
  // "push, duty_pulse, restart"
  [[nodiscard]] std::string actions() const;
  // `plant`, taking the endpoint's disturbances while it exists (it must not outlive the endpoint).
  [[nodiscard]] std::unique_ptr<plant::Plant> controlled(std::unique_ptr<plant::Plant> plant);
  // Every disturbance applied so far, with its model time.
  [[nodiscard]] std::vector<plant::AppliedDisturbance> applied() const;
  [[nodiscard]] std::vector<plant::DisturbanceKind> offered() const;

 private:
  // The server (declared last) goes first: it withdraws what it waits for from the controls.
  std::unique_ptr<plant::PlantControls> controls_;
  std::unique_ptr<plant_control::PlantControlServer> server_;
};

}  // namespace duet::cli
