#pragma once
// The plant-control endpoint (docs/LINK.md, "Plant control"): the process that serves a plant (duet pil, duet plant
// serve) takes disturbances for it over TCP, on this machine only, as JSON lines: a connection gets the plant's
// `description` first; a `plant` request is checked, handed to PlantControls and answered once the plant applied it,
// with the model time it acts from, or refused with the problem. What one connection has applied is told to the
// others too, so that every dashboard shows the last push whoever gave it. Serves on a thread of its own.

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "duet/plant/plant_controls.hpp"
#include "duet/support/result.hpp"

namespace duet::plant_control {

struct ServerOptions {
  std::string host = "127.0.0.1";  // a loopback address ("localhost" is 127.0.0.1); anything else is refused
  std::uint16_t port = 0;          // 0: a free port
  std::string plant;               // its name, for the description
  // A request the plant has not applied by then (no firmware ticks it: not started, stopped in a debugger) is
  // withdrawn and refused, so that it does not land later by surprise.
  std::chrono::milliseconds apply_within{2000};
  std::size_t max_connections = 8;
};

class PlantControlServer {
 public:
  // Listens; the failure names the address. `controls` must outlive the server.
  [[nodiscard]] static Result<std::unique_ptr<PlantControlServer>> start(plant::PlantControls& controls,
                                                                         ServerOptions options);
  // Stops serving; requests still waiting are withdrawn.
  ~PlantControlServer();
  PlantControlServer(const PlantControlServer&) = delete;
  PlantControlServer& operator=(const PlantControlServer&) = delete;

  // "127.0.0.1:40312": where it listens, with the port taken for 0.
  [[nodiscard]] const std::string& address() const;

  class Impl;

 private:
  explicit PlantControlServer(std::shared_ptr<Impl> impl);
  std::shared_ptr<Impl> impl_;
};

}  // namespace duet::plant_control
