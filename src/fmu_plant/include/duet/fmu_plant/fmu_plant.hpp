#pragma once
// An imported co-simulation FMU as the plant of a simulation (`duet sim MODEL.yaml --plant X.fmu --connect M.yaml`):
// the controller's writes to its output resources drive the FMU's inputs, its reads of input resources are
// answered by the FMU's outputs, as the mapping file says (fmu_mapping.hpp). The FMU steps at the controller's base
// period (or at its own fixed step, several times per period) in lock-step: the inputs written during one tick
// are set before the step that follows it, and the outputs read during a tick are those the last step ended with,
// so that no Get follows a Set without a step between, as FMI demands.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "duet/fmi/imported_fmu.hpp"
#include "duet/fmu_plant/fmu_mapping.hpp"
#include "duet/plant/plant.hpp"
#include "duet/support/result.hpp"

namespace duet::fmu_plant {

class FmuPlant : public plant::Plant {
 public:
  struct Options {
    std::filesystem::path fmu;
    FmuMapping mapping;
    fmi::FmuLog log;  // the FMU's messages
  };
  // Opens the FMU and checks the mapping against it.
  [[nodiscard]] static Result<std::unique_ptr<FmuPlant>> load(Options options);

  // Sets the mapping's values and initialises the FMU at time 0, to step at `base_period_s`.
  [[nodiscard]] Status start(double base_period_s) override;

  void advance(double time_s, const plant::RaiseInterrupt& raise) override;
  void write(std::string_view resource, std::span<const double> values) override;
  void read(std::string_view resource, std::span<double> values) override;
  [[nodiscard]] std::vector<Observable> observables() const override;
  void observe(std::span<double> values) const override;
  [[nodiscard]] std::optional<Halt> halted() const override { return halt_; }

  [[nodiscard]] const fmi::ImportedFmu& fmu() const { return *fmu_; }

 private:
  // One mapped or observed FMU variable and its value: the last set (inputs) or the last fetched (the others).
  struct Slot {
    const fmi::Variable* variable;
    double value = 0;
  };
  FmuPlant(std::unique_ptr<fmi::ImportedFmu> fmu, FmuMapping mapping);
  Status fetch();  // every output and observed variable, after a step
  void fail(std::string reason);

  std::unique_ptr<fmi::ImportedFmu> fmu_;
  FmuMapping mapping_;
  std::vector<Slot> inputs_;   // mapping_.inputs' order
  std::vector<Slot> fetched_;  // mapping_.outputs' order, then the observables'
  std::size_t observed_from_ = 0;
  std::optional<Halt> halt_;
  bool started_ = false;
};

}  // namespace duet::fmu_plant
