#pragma once
// The simulated self-balancing robot of the thesis (STM32MP15 + "Balance Car daughterboard"): a planar inverted
// pendulum on two wheels driven by DC motors through a TB6612FNG, with an MPU6500 on SPI5, hall encoders on TIM2/TIM4,
// an HC-SR04 on TIM5, the battery on ADC1 channel 6 and a channel to the Linux side. The model sees it through the
// resources of its hardware blocks (names and values: src/plant/balbot/README.md) and the interrupts it raises.
//
// Time: advance(t) moves the physics to t (fixed-step RK4, steps of at most 1 ms, split where an interrupt task
// changes the drive) and raises every interrupt due at or before t, in time order, with the state of that instant
// visible to the task. Writes between advance() calls act from the last advance() time on. Single-threaded; no call
// allocates once the plant is built (except the first access to an unknown resource name, which is remembered).

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "duet/plant/balbot/balbot_parameters.hpp"
#include "duet/plant/balbot/balbot_scenario.hpp"
#include "duet/plant/balbot/balbot_truth.hpp"
#include "duet/plant/plant.hpp"

namespace duet::plant {

class BalbotSimulation;

class BalbotPlant final : public Plant {
 public:
  explicit BalbotPlant(const BalbotScenario& scenario = {}, const BalbotParameters& parameters = {});
  ~BalbotPlant() override;

  void advance(double time_s, const RaiseInterrupt& raise) override;
  void write(std::string_view resource, std::span<const double> values) override;
  void read(std::string_view resource, std::span<double> values) override;
  // The truth's values (BalbotTruth::names()), but time.
  [[nodiscard]] std::vector<Observable> observables() const override;
  void observe(std::span<double> values) const override;
  // push (force_n, duration_s), duty_pulse (duty, duration_s) and restart: README.md, "Disturbances during a run".
  [[nodiscard]] std::vector<DisturbanceKind> disturbances() const override;
  void disturb(const Disturbance& disturbance, double time_s) override;

  // The state now (inside an interrupt task: at the interrupt's instant).
  [[nodiscard]] BalbotTruth truth() const;
  // The last message the model sent to the Linux side ("ipc:app").
  [[nodiscard]] std::span<const std::uint8_t> message_to_linux() const;
  // Resource names the model used that the robot does not have, each once, in order of first use.
  [[nodiscard]] const std::vector<std::string>& unknown_resources() const;
  // SPI5 transactions refused because the previous one's DMA had not completed.
  [[nodiscard]] std::uint64_t refused_spi_transactions() const;

 private:
  std::unique_ptr<BalbotSimulation> simulation_;
};

// The robot with the scenario's defaults and that noise seed (what make_plant("balbot", seed) builds).
[[nodiscard]] std::unique_ptr<BalbotPlant> make_balbot_plant(std::uint64_t seed);
[[nodiscard]] std::unique_ptr<BalbotPlant> make_balbot_plant(const BalbotScenario& scenario);

}  // namespace duet::plant
