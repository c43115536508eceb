#pragma once
// A plant that is itself a model (`duet sim controller.yaml --plant robot.yaml`): the plant model runs at its own base
// rate, in lock-step with the controller. They meet on named resources: what the controller's hardware blocks write
// (a PWM duty on "pwm:TIM1/1") the plant model reads with a PlantInput block of that resource, and what the plant
// model writes with a PlantOutput block the controller's hardware blocks read (an ADC's samples on "adc:ADC1/6").

#include <memory>
#include <string>

#include "duet/model/model.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::model {

class ModelPlant : public plant::Plant {
 public:
  // Loads and checks the plant model; its diagnostics (warnings too) are in `diagnostics` of the failure or kept in
  // warnings().
  static Result<std::unique_ptr<ModelPlant>> load(const std::string& path);

  void advance(double time_s, const plant::RaiseInterrupt& raise) override;
  void write(std::string_view resource, std::span<const double> values) override;
  void read(std::string_view resource, std::span<double> values) override;

  [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }
  [[nodiscard]] Interpreter& interpreter() { return runner_->interpreter(); }

 private:
  ModelPlant() = default;

  std::unique_ptr<Model> model_;
  std::unique_ptr<Program> program_;
  plant::Loopback resources_;  // where the two models meet
  std::unique_ptr<ModelRunner> runner_;
  std::uint64_t ticks_ = 0;
  std::vector<std::string> warnings_;
};

}  // namespace duet::model
