#pragma once
// What ImportedFmu asks of one FMI version (inside src/fmi only): an instance made from a loaded library, its
// typed calls behind numbers, and the standard's statuses turned into duet's Results with the simulation time and
// the FMU's last message.

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "duet/fmi/imported_fmu.hpp"
#include "duet/fmi/model_description.hpp"
#include "duet/support/result.hpp"

namespace duet::fmi {

// The instance environment both versions hand their FMU: its log lines forwarded, the last one kept for reports.
struct FmuMessages {
  std::string model_name;
  FmuLog log;
  std::string last;
  void add(std::string_view status, std::string_view message);
};

// The functions an importer takes from the library, looked up by name; every missing one is remembered.
class Symbols {
 public:
  explicit Symbols(void* library) : library_(library) {}
  template <typename Function>
  Function* find(const char* name) {
    return reinterpret_cast<Function*>(find_address(name));  // NOLINT: dlsym's void* is the function's address
  }
  [[nodiscard]] const std::string& missing() const { return missing_; }  // "fmi3DoStep, fmi3Terminate"

 private:
  void* find_address(const char* name);
  void* library_;
  std::string missing_;
};

struct StepResult {
  bool stop_requested = false;
  double reached_s = 0;  // where the FMU says the step ended
};

class FmuInstance {
 public:
  FmuInstance(const FmuInstance&) = delete;
  FmuInstance& operator=(const FmuInstance&) = delete;
  virtual ~FmuInstance() = default;

  virtual Status set(const Variable& variable, double value) = 0;
  virtual Result<double> get(const Variable& variable) = 0;
  virtual Status enter_initialization(double start_s) = 0;
  virtual Status exit_initialization() = 0;
  virtual Result<StepResult> step(double point_s, double step_s) = 0;

 protected:
  explicit FmuInstance(FmuMessages& messages) : messages_(messages) {}

  // The standard's status (both versions number OK..Fatal alike) of `function` called at `time_s_`: OK and Warning
  // (logged) pass; Discard, Error and Fatal fail, the last two for good.
  Status check(std::string_view function, int status);
  [[nodiscard]] Failure failure(std::string_view function, std::string_view what) const;
  [[nodiscard]] Status usable() const;  // refuses any call after an Error or a Fatal
  [[nodiscard]] bool fatal() const { return fatal_; }
  [[nodiscard]] bool failed() const { return failed_; }
  [[nodiscard]] FmuMessages& messages() { return messages_; }

  double time_s_ = 0;  // the simulation time the calls are made at, for reports

 private:
  FmuMessages& messages_;
  bool failed_ = false;
  bool fatal_ = false;
};

// Instantiates the FMU of `description` from the loaded `library`, its files unpacked in `folder`.
Result<std::unique_ptr<FmuInstance>> make_fmi2_instance(void* library, const ModelDescription& description,
                                                        const std::filesystem::path& folder, FmuMessages& messages);
Result<std::unique_ptr<FmuInstance>> make_fmi3_instance(void* library, const ModelDescription& description,
                                                        const std::filesystem::path& folder, FmuMessages& messages);

// `value` as the integer type of `variable`, refused unless it is a whole number that type holds.
template <typename Integer>
Result<Integer> whole_number(const Variable& variable, double value) {
  if (value != std::trunc(value) || !(value >= static_cast<double>(std::numeric_limits<Integer>::lowest())) ||
      !(value < static_cast<double>(std::numeric_limits<Integer>::max()) + 1.0)) {
    return Failure{variable.name + " is " + std::string{xml_name(variable.type)} + ": " + std::to_string(value) +
                   " is not one of its values"};
  }
  return static_cast<Integer>(value);
}

// "0.5": a time as a report shows it.
std::string time_text(double time_s);

}  // namespace duet::fmi
