// FMI 2.0 co-simulation behind FmuInstance.
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "duet/fmi/fmi2_api.h"
#include "fmu_instance.hpp"

namespace duet::fmi {
namespace {

// 2.0's logger formats like printf; the message is formatted here before it is forwarded.
void log_fmi2(fmi2ComponentEnvironment environment, fmi2String, fmi2Status status, fmi2String, fmi2String message,
              ...) {
  auto& messages = *static_cast<FmuMessages*>(environment);
  constexpr const char* names[] = {"OK", "Warning", "Discard", "Error", "Fatal", "Pending"};
  std::va_list arguments;
  va_start(arguments, message);  // NOLINT: the standard's logger is variadic
  std::va_list again;
  va_copy(again, arguments);
  const int length = message == nullptr ? 0 : std::vsnprintf(nullptr, 0, message, arguments);
  std::string text(length > 0 ? static_cast<std::size_t>(length) : 0U, '\0');
  if (length > 0) (void)std::vsnprintf(text.data(), text.size() + 1, message, again);
  va_end(again);
  va_end(arguments);
  const auto index = static_cast<std::size_t>(status);
  messages.add(index < std::size(names) ? names[index] : "?", text);
}

std::string resource_uri(const std::filesystem::path& folder) {
  // A file URI; every byte outside the unreserved set and '/' percent-encoded.
  std::string uri = "file://";
  constexpr char hex[] = "0123456789ABCDEF";
  for (const char byte : (folder / "resources").string()) {
    const auto c = static_cast<unsigned char>(byte);
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '/' ||
                       c == '-' || c == '_' || c == '.' || c == '~';
    if (plain) {
      uri += static_cast<char>(c);
    } else {
      uri += '%';
      uri += hex[c >> 4U];
      uri += hex[c & 0xFU];
    }
  }
  return uri;
}

struct Fmi2Functions {
  fmi2InstantiateTYPE* instantiate;
  fmi2FreeInstanceTYPE* free_instance;
  fmi2SetupExperimentTYPE* setup_experiment;
  fmi2EnterInitializationModeTYPE* enter_initialization_mode;
  fmi2ExitInitializationModeTYPE* exit_initialization_mode;
  fmi2TerminateTYPE* terminate;
  fmi2GetRealTYPE* get_real;
  fmi2GetIntegerTYPE* get_integer;
  fmi2GetBooleanTYPE* get_boolean;
  fmi2SetRealTYPE* set_real;
  fmi2SetIntegerTYPE* set_integer;
  fmi2SetBooleanTYPE* set_boolean;
  fmi2DoStepTYPE* do_step;
  fmi2GetBooleanStatusTYPE* get_boolean_status;
  fmi2GetRealStatusTYPE* get_real_status;
};

class Fmi2Instance : public FmuInstance {
 public:
  Fmi2Instance(const Fmi2Functions& functions, FmuMessages& messages)
      : FmuInstance(messages),
        functions_(functions),
        callbacks_{.logger = log_fmi2,
                   .allocateMemory = std::calloc,
                   .freeMemory = std::free,
                   .stepFinished = nullptr,
                   .componentEnvironment = &messages} {}
  Fmi2Instance(const Fmi2Instance&) = delete;
  Fmi2Instance& operator=(const Fmi2Instance&) = delete;

  ~Fmi2Instance() override {
    if (component_ == nullptr || fatal()) return;
    if (initialized_ && !failed()) (void)functions_.terminate(component_);
    functions_.free_instance(component_);
  }

  Status instantiate(const ModelDescription& description, const std::filesystem::path& folder) {
    const std::string uri = resource_uri(folder);
    component_ = functions_.instantiate(description.model_name.c_str(), fmi2CoSimulation, description.token.c_str(),
                                        uri.c_str(), &callbacks_, fmi2False, fmi2True);
    if (component_ == nullptr) return failure("fmi2Instantiate", "returned no instance");
    return done();
  }

  Status set(const Variable& variable, double value) override {
    if (auto ok = usable(); !ok) return ok;
    const fmi2ValueReference reference = variable.value_reference;
    switch (variable.type) {
      case VariableType::real: return check("fmi2SetReal", functions_.set_real(component_, &reference, 1, &value));
      case VariableType::integer:
      case VariableType::enumeration: {
        const auto whole = whole_number<fmi2Integer>(variable, value);
        if (!whole) return Failure{whole.error()};
        return check("fmi2SetInteger", functions_.set_integer(component_, &reference, 1, &whole.value()));
      }
      case VariableType::boolean: {
        const fmi2Boolean truth = value != 0 ? fmi2True : fmi2False;
        return check("fmi2SetBoolean", functions_.set_boolean(component_, &reference, 1, &truth));
      }
      default: return Failure{variable.name + " is a " + std::string{xml_name(variable.type)} + ": not a number"};
    }
  }

  Result<double> get(const Variable& variable) override {
    if (auto ok = usable(); !ok) return Failure{ok.error()};
    const fmi2ValueReference reference = variable.value_reference;
    Status status = done();
    double value = 0;
    switch (variable.type) {
      case VariableType::real:
        status = check("fmi2GetReal", functions_.get_real(component_, &reference, 1, &value));
        break;
      case VariableType::integer:
      case VariableType::enumeration: {
        fmi2Integer whole = 0;
        status = check("fmi2GetInteger", functions_.get_integer(component_, &reference, 1, &whole));
        value = whole;
        break;
      }
      case VariableType::boolean: {
        fmi2Boolean truth = fmi2False;
        status = check("fmi2GetBoolean", functions_.get_boolean(component_, &reference, 1, &truth));
        value = truth != fmi2False ? 1.0 : 0.0;
        break;
      }
      default: return Failure{variable.name + " is a " + std::string{xml_name(variable.type)} + ": not a number"};
    }
    if (!status) return Failure{status.error()};
    return value;
  }

  Status enter_initialization(double start_s) override {
    time_s_ = start_s;
    if (auto ok = check("fmi2SetupExperiment",
                        functions_.setup_experiment(component_, fmi2False, 0.0, start_s, fmi2False, 0.0));
        !ok)
      return ok;
    return check("fmi2EnterInitializationMode", functions_.enter_initialization_mode(component_));
  }

  Status exit_initialization() override {
    auto exited = check("fmi2ExitInitializationMode", functions_.exit_initialization_mode(component_));
    initialized_ = exited.ok();  // from here on Terminate is the way out
    return exited;
  }

  Result<StepResult> step(double point_s, double step_s) override {
    if (auto ok = usable(); !ok) return Failure{ok.error()};
    time_s_ = point_s;
    const fmi2Status status = functions_.do_step(component_, point_s, step_s, fmi2True);
    if (status == fmi2Discard) {
      // A step cut short: the FMU asks to stop when fmi2Terminated says so, and tells how far it came.
      fmi2Boolean terminated = fmi2False;
      if (functions_.get_boolean_status(component_, fmi2Terminated, &terminated) == fmi2OK && terminated != fmi2False) {
        fmi2Real reached = point_s + step_s;
        if (functions_.get_real_status(component_, fmi2LastSuccessfulTime, &reached) != fmi2OK)
          reached = point_s + step_s;
        return StepResult{.stop_requested = true, .reached_s = reached};
      }
    }
    if (auto ok = check("fmi2DoStep", status); !ok) return Failure{ok.error()};
    return StepResult{.stop_requested = false, .reached_s = point_s + step_s};
  }

 private:
  Fmi2Functions functions_;
  fmi2CallbackFunctions callbacks_;  // the FMU may keep a pointer to it for its whole life
  fmi2Component component_ = nullptr;
  bool initialized_ = false;
};

}  // namespace

Result<std::unique_ptr<FmuInstance>> make_fmi2_instance(void* library, const ModelDescription& description,
                                                        const std::filesystem::path& folder, FmuMessages& messages) {
  Symbols symbols{library};
  const Fmi2Functions functions{
      .instantiate = symbols.find<fmi2InstantiateTYPE>("fmi2Instantiate"),
      .free_instance = symbols.find<fmi2FreeInstanceTYPE>("fmi2FreeInstance"),
      .setup_experiment = symbols.find<fmi2SetupExperimentTYPE>("fmi2SetupExperiment"),
      .enter_initialization_mode = symbols.find<fmi2EnterInitializationModeTYPE>("fmi2EnterInitializationMode"),
      .exit_initialization_mode = symbols.find<fmi2ExitInitializationModeTYPE>("fmi2ExitInitializationMode"),
      .terminate = symbols.find<fmi2TerminateTYPE>("fmi2Terminate"),
      .get_real = symbols.find<fmi2GetRealTYPE>("fmi2GetReal"),
      .get_integer = symbols.find<fmi2GetIntegerTYPE>("fmi2GetInteger"),
      .get_boolean = symbols.find<fmi2GetBooleanTYPE>("fmi2GetBoolean"),
      .set_real = symbols.find<fmi2SetRealTYPE>("fmi2SetReal"),
      .set_integer = symbols.find<fmi2SetIntegerTYPE>("fmi2SetInteger"),
      .set_boolean = symbols.find<fmi2SetBooleanTYPE>("fmi2SetBoolean"),
      .do_step = symbols.find<fmi2DoStepTYPE>("fmi2DoStep"),
      .get_boolean_status = symbols.find<fmi2GetBooleanStatusTYPE>("fmi2GetBooleanStatus"),
      .get_real_status = symbols.find<fmi2GetRealStatusTYPE>("fmi2GetRealStatus")};
  if (!symbols.missing().empty()) return Failure{"the library lacks " + symbols.missing() + ", which duet calls"};
  auto instance = std::make_unique<Fmi2Instance>(functions, messages);
  if (auto made = instance->instantiate(description, folder); !made) return Failure{made.error()};
  return std::unique_ptr<FmuInstance>{std::move(instance)};
}

}  // namespace duet::fmi
