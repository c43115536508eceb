#pragma once
// A co-simulation FMU of FMI 2.0 or 3.0 run by duet (docs/FMI.md, "Import"): unpacked into a private folder, its
// library loaded, one instance made, its variables set and read by name, stepped at communication points
// t_i = t0 + i·h. Behind this one interface the two versions' calls differ only inside imported_fmu.cpp's
// neighbours (fmi2_instance.cpp, fmi3_instance.cpp).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "duet/fmi/model_description.hpp"
#include "duet/support/result.hpp"

namespace duet::fmi {

// Where the FMU's own messages go, already prefixed with its model name ("Lag: Warning: ...").
using FmuLog = std::function<void(std::string_view line)>;

class FmuInstance;  // one version's calls (fmu_instance.hpp)

class ImportedFmu {
 public:
  // Opens `file`, refusing (with the reason) an FMU whose description is wrong, that lacks a Linux x86_64 library
  // for its FMI version, a function duet calls, or that allows one instance per process while one is alive; then
  // instantiates it (in the Instantiated state: set() start values and parameters next).
  [[nodiscard]] static Result<std::unique_ptr<ImportedFmu>> open(const std::filesystem::path& file, FmuLog log);
  ImportedFmu(const ImportedFmu&) = delete;
  ImportedFmu& operator=(const ImportedFmu&) = delete;
  ~ImportedFmu();  // Terminate when legal, FreeInstance unless the FMU was fatal, and the library unloaded

  [[nodiscard]] const ModelDescription& description() const { return description_; }
  [[nodiscard]] const Variable* variable(std::string_view name) const;

  // A number through the variable's typed call (Real/Float64..., Integer/Int32..., Boolean as 0 or 1). Strings,
  // binaries and clocks are refused.
  [[nodiscard]] Status set(const Variable& variable, double value);
  [[nodiscard]] Result<double> get(const Variable& variable);

  // Initialisation from `start_s` (2.0 SetupExperiment and Enter/ExitInitializationMode, 3.0 Enter/Exit), with
  // communication steps of `step_s`, or of the FMU's fixedInternalStepSize several times per `step_s` when it
  // declares one (refused when that does not divide `step_s`). `set_inputs` runs in initialisation mode.
  [[nodiscard]] Status initialize(double start_s, double step_s, const std::function<Status()>& set_inputs);

  // Steps up to `time_s` (every communication point not later than it). After a stop request or a failure no
  // further step is made: failures come back as the error, a stop request as stop_request().
  [[nodiscard]] Status advance_to(double time_s);
  [[nodiscard]] const std::optional<std::string>& stop_request() const { return stop_request_; }
  [[nodiscard]] double time() const;  // the last communication point reached
  [[nodiscard]] std::uint64_t steps() const { return steps_; }

 private:
  struct Loaded;  // the folder and the library, unloaded after the instance is freed
  ImportedFmu(ModelDescription description, std::unique_ptr<Loaded> loaded);

  ModelDescription description_;
  std::unique_ptr<Loaded> loaded_;
  std::unique_ptr<FmuInstance> instance_;
  double start_s_ = 0;
  double step_s_ = 0;  // the communication step the FMU is given
  std::uint64_t steps_ = 0;
  std::optional<std::string> stop_request_;
  std::optional<std::string> failure_;
};

}  // namespace duet::fmi
