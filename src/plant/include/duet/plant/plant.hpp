#pragma once
// What a simulated model is connected to: a plant sees the model's hardware blocks as named resources — a pin
// ("gpio:LED0"), a PWM channel ("pwm:TIM1/1"), an ADC ("adc:ADC1/6"), ... — reads what the model writes to its
// outputs, answers what the model reads from its inputs, and raises the interrupts that trigger the model's
// interrupt tasks. Time is the simulation's: the plant moves only when advance() is called, so a run is the same
// every time.

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::plant {

// Raises the interrupt of that name now; the simulation runs the interrupt task it triggers.
using RaiseInterrupt = std::function<void(std::string_view interrupt)>;

// A disturbance a plant offers to whoever watches a run (a push, a restart), described so that a page or a script
// can offer it without knowing the plant: its name and its arguments, each a number within limits.
struct DisturbanceArgument {
  std::string name;  // "force_n"
  std::string unit;  // "N"
  double minimum = 0;
  double maximum = 0;
  double default_value = 0;
};
struct DisturbanceKind {
  std::string name;     // "push"
  std::string summary;  // what it does, in a few words
  std::vector<DisturbanceArgument> arguments;
};
// One disturbance asked for: a kind's name and a value per argument, in the kind's order.
struct Disturbance {
  std::string name;
  std::vector<double> arguments;
};

class Plant {
 public:
  Plant() = default;
  Plant(const Plant&) = delete;
  Plant& operator=(const Plant&) = delete;
  virtual ~Plant() = default;

  // Once, before the first advance(): the model's base period, the pace at which advance() will come. A plant that
  // steps with the model (an imported FMU) initialises here, since only the model knows its period; a failure ends
  // the run before it begins.
  [[nodiscard]] virtual Status start(double base_period_s) {
    (void)base_period_s;
    return done();
  }
  // Moves the plant's time on to `time_s`, raising the interrupts that happen by then.
  virtual void advance(double time_s, const RaiseInterrupt& raise) = 0;
  // The model drives an output resource (an actuator) with these element values.
  virtual void write(std::string_view resource, std::span<const double> values) = 0;
  // The model reads an input resource (a sensor); the plant fills every element.
  virtual void read(std::string_view resource, std::span<double> values) = 0;

  // What the plant shows of itself beside the model's signals (a simulation records them as columns "plant.NAME"):
  // names with their units, and the values now, in that order. Nothing unless a plant says.
  struct Observable {
    std::string name;
    std::string unit;
  };
  [[nodiscard]] virtual std::vector<Observable> observables() const { return {}; }
  virtual void observe(std::span<double> values) const { (void)values; }

  // Why the plant cannot go on, once it cannot (an imported FMU that failed, or asked to stop); nothing while it can.
  // A simulation stops there: a failure fails it, a request ends it early.
  struct Halt {
    std::string reason;
    bool failed = false;
  };
  [[nodiscard]] virtual std::optional<Halt> halted() const { return std::nullopt; }

  // The disturbances the plant offers; none unless a plant says.
  [[nodiscard]] virtual std::vector<DisturbanceKind> disturbances() const { return {}; }
  // Between two advance() calls: `disturbance` (one of disturbances(), its arguments within their limits) acts from
  // `time_s` on, the time the next advance() moves to, exactly as if the plant had been made with it planned for
  // then. PlantControls (plant_controls.hpp) calls it on the plant's thread.
  virtual void disturb(const Disturbance& disturbance, double time_s) {
    (void)disturbance;
    (void)time_s;
  }
};

// A plant that holds the last value written to each resource and reads back whatever was written to it (zeros for a
// resource never written): outputs can be looked at, and a model can read its own outputs as inputs.
class Loopback : public Plant {
 public:
  void advance(double time_s, const RaiseInterrupt& raise) override;
  void write(std::string_view resource, std::span<const double> values) override;
  void read(std::string_view resource, std::span<double> values) override;

  [[nodiscard]] std::vector<double> value(std::string_view resource) const;
  [[nodiscard]] std::size_t writes() const { return writes_; }

 private:
  std::vector<std::pair<std::string, std::vector<double>>> values_;
  std::size_t writes_ = 0;
};

// The plants `duet sim --plant NAME` knows, by name: "none" (a Loopback), "balbot" (the self-balancing robot,
// src/plant/balbot/README.md). `seed` makes noisy plants repeatable.
[[nodiscard]] Result<std::unique_ptr<Plant>> make_plant(std::string_view name, std::uint64_t seed);
[[nodiscard]] std::vector<std::string> plant_names();

}  // namespace duet::plant
