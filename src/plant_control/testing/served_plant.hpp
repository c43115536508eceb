#pragma once
// For tests: what duet pil does for the dashboards' plant control, in-process: a plant that offers a push and a
// restart, served in a thread of its own at a tick a millisecond, and its plant-control endpoint.

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>

#include "duet/plant/plant_controls.hpp"
#include "duet/plant_control/plant_control_server.hpp"

namespace duet::plant_control::testing {

class ShovablePlant : public plant::Plant {
 public:
  void advance(double, const plant::RaiseInterrupt&) override {}
  void write(std::string_view, std::span<const double>) override {}
  void read(std::string_view, std::span<double>) override {}
  [[nodiscard]] std::vector<plant::DisturbanceKind> disturbances() const override { return kinds(); }
  static std::vector<plant::DisturbanceKind> kinds() {
    return {{"push", "a shove", {{"force_n", "N", -50, 50, 5}, {"duration_s", "s", 0.001, 1, 0.05}}},
            {"restart", "again", {}}};
  }
};

// Ticks `controls`' plant until destroyed.
class TickingPlant {
 public:
  explicit TickingPlant(plant::PlantControls& controls)
      : plant_(std::make_unique<ShovablePlant>(), controls), thread_([this] {
          for (int tick = 1; !stop_.load(); ++tick) {
            plant_.advance(tick * 1e-3, {});
            std::this_thread::sleep_for(std::chrono::milliseconds{1});
          }
        }) {}
  ~TickingPlant() {
    stop_ = true;
    thread_.join();
  }
  TickingPlant(const TickingPlant&) = delete;
  TickingPlant& operator=(const TickingPlant&) = delete;

 private:
  plant::ControlledPlant plant_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// The plant ticking and its endpoint listening on a free port.
class ServedPlant {
 public:
  ServedPlant() {
    auto started = PlantControlServer::start(controls_, {.plant = "shovable"});
    if (started) server_ = std::move(started).value();
  }
  [[nodiscard]] bool listening() const { return server_ != nullptr; }
  [[nodiscard]] std::string host() const { return server_->address().substr(0, server_->address().rfind(':')); }
  [[nodiscard]] std::uint16_t port() const {
    return static_cast<std::uint16_t>(std::stoi(server_->address().substr(server_->address().rfind(':') + 1)));
  }
  void stop_serving() { server_.reset(); }
  [[nodiscard]] plant::PlantControls& controls() { return controls_; }

 private:
  plant::PlantControls controls_{ShovablePlant::kinds()};
  TickingPlant ticking_{controls_};
  std::unique_ptr<PlantControlServer> server_;
};

}  // namespace duet::plant_control::testing
