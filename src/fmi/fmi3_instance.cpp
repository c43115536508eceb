// FMI 3.0 co-simulation behind FmuInstance.
#include <filesystem>
#include <string>
#include <type_traits>

#include "duet/fmi/fmi3_api.h"
#include "fmu_instance.hpp"

namespace duet::fmi {
namespace {

void log_fmi3(fmi3InstanceEnvironment environment, fmi3Status status, fmi3String, fmi3String message) {
  constexpr const char* names[] = {"OK", "Warning", "Discard", "Error", "Fatal"};
  const auto index = static_cast<std::size_t>(status);
  static_cast<FmuMessages*>(environment)
      ->add(index < std::size(names) ? names[index] : "?", message == nullptr ? "" : message);
}

// The getter and setter of one value type.
template <typename Value>
struct Accessors {
  fmi3Status (*get)(fmi3Instance, const fmi3ValueReference[], size_t, Value[], size_t);
  fmi3Status (*set)(fmi3Instance, const fmi3ValueReference[], size_t, const Value[], size_t);
};

struct Fmi3Functions {
  fmi3InstantiateCoSimulationTYPE* instantiate;
  fmi3FreeInstanceTYPE* free_instance;
  fmi3EnterInitializationModeTYPE* enter_initialization_mode;
  fmi3ExitInitializationModeTYPE* exit_initialization_mode;
  fmi3TerminateTYPE* terminate;
  fmi3DoStepTYPE* do_step;
  Accessors<fmi3Float32> float32;
  Accessors<fmi3Float64> float64;
  Accessors<fmi3Int8> int8;
  Accessors<fmi3UInt8> uint8;
  Accessors<fmi3Int16> int16;
  Accessors<fmi3UInt16> uint16;
  Accessors<fmi3Int32> int32;
  Accessors<fmi3UInt32> uint32;
  Accessors<fmi3Int64> int64;
  Accessors<fmi3UInt64> uint64;
  Accessors<fmi3Boolean> boolean;
};

class Fmi3Instance : public FmuInstance {
 public:
  Fmi3Instance(const Fmi3Functions& functions, FmuMessages& messages) : FmuInstance(messages), functions_(functions) {}
  Fmi3Instance(const Fmi3Instance&) = delete;
  Fmi3Instance& operator=(const Fmi3Instance&) = delete;

  ~Fmi3Instance() override {
    if (instance_ == nullptr || fatal()) return;
    if (initialized_ && !failed()) (void)functions_.terminate(instance_);
    functions_.free_instance(instance_);
  }

  Status instantiate(const ModelDescription& description, const std::filesystem::path& folder) {
    // A plain path with a trailing separator, or none when the FMU brings no resources.
    const std::filesystem::path resources = folder / "resources";
    const std::string resource_path = resources.string() + "/";
    const bool has_resources = std::filesystem::is_directory(resources);
    instance_ = functions_.instantiate(description.model_name.c_str(), description.token.c_str(),
                                       has_resources ? resource_path.c_str() : nullptr, fmi3False, fmi3True, fmi3False,
                                       fmi3False, nullptr, 0, &messages(), log_fmi3, nullptr);
    if (instance_ == nullptr) return failure("fmi3InstantiateCoSimulation", "returned no instance");
    return done();
  }

  Status set(const Variable& variable, double value) override {
    if (auto ok = usable(); !ok) return ok;
    switch (variable.type) {
      case VariableType::float32: return set_as("fmi3SetFloat32", functions_.float32, variable, value);
      case VariableType::float64: return set_as("fmi3SetFloat64", functions_.float64, variable, value);
      case VariableType::int8: return set_as("fmi3SetInt8", functions_.int8, variable, value);
      case VariableType::uint8: return set_as("fmi3SetUInt8", functions_.uint8, variable, value);
      case VariableType::int16: return set_as("fmi3SetInt16", functions_.int16, variable, value);
      case VariableType::uint16: return set_as("fmi3SetUInt16", functions_.uint16, variable, value);
      case VariableType::int32: return set_as("fmi3SetInt32", functions_.int32, variable, value);
      case VariableType::uint32: return set_as("fmi3SetUInt32", functions_.uint32, variable, value);
      case VariableType::int64:
      case VariableType::enumeration: return set_as("fmi3SetInt64", functions_.int64, variable, value);
      case VariableType::uint64: return set_as("fmi3SetUInt64", functions_.uint64, variable, value);
      case VariableType::boolean: return set_as("fmi3SetBoolean", functions_.boolean, variable, value);
      default: return Failure{variable.name + " is a " + std::string{xml_name(variable.type)} + ": not a number"};
    }
  }

  Result<double> get(const Variable& variable) override {
    if (auto ok = usable(); !ok) return Failure{ok.error()};
    switch (variable.type) {
      case VariableType::float32: return get_as("fmi3GetFloat32", functions_.float32, variable);
      case VariableType::float64: return get_as("fmi3GetFloat64", functions_.float64, variable);
      case VariableType::int8: return get_as("fmi3GetInt8", functions_.int8, variable);
      case VariableType::uint8: return get_as("fmi3GetUInt8", functions_.uint8, variable);
      case VariableType::int16: return get_as("fmi3GetInt16", functions_.int16, variable);
      case VariableType::uint16: return get_as("fmi3GetUInt16", functions_.uint16, variable);
      case VariableType::int32: return get_as("fmi3GetInt32", functions_.int32, variable);
      case VariableType::uint32: return get_as("fmi3GetUInt32", functions_.uint32, variable);
      case VariableType::int64:
      case VariableType::enumeration: return get_as("fmi3GetInt64", functions_.int64, variable);
      case VariableType::uint64: return get_as("fmi3GetUInt64", functions_.uint64, variable);
      case VariableType::boolean: return get_as("fmi3GetBoolean", functions_.boolean, variable);
      default: return Failure{variable.name + " is a " + std::string{xml_name(variable.type)} + ": not a number"};
    }
  }

  Status enter_initialization(double start_s) override {
    time_s_ = start_s;
    return check("fmi3EnterInitializationMode",
                 functions_.enter_initialization_mode(instance_, fmi3False, 0.0, start_s, fmi3False, 0.0));
  }

  Status exit_initialization() override {
    auto exited = check("fmi3ExitInitializationMode", functions_.exit_initialization_mode(instance_));
    initialized_ = exited.ok();  // from here on Terminate is the way out
    return exited;
  }

  Result<StepResult> step(double point_s, double step_s) override {
    if (auto ok = usable(); !ok) return Failure{ok.error()};
    time_s_ = point_s;
    fmi3Boolean event_handling_needed = fmi3False;
    fmi3Boolean terminate = fmi3False;
    fmi3Boolean early_return = fmi3False;
    fmi3Float64 reached = point_s + step_s;
    const fmi3Status status = functions_.do_step(instance_, point_s, step_s, fmi3True, &event_handling_needed,
                                                 &terminate, &early_return, &reached);
    if (auto ok = check("fmi3DoStep", status); !ok) return Failure{ok.error()};
    return StepResult{.stop_requested = terminate, .reached_s = reached};
  }

 private:
  template <typename Value>
  Status set_as(const char* function, const Accessors<Value>& accessors, const Variable& variable, double value) {
    const fmi3ValueReference reference = variable.value_reference;
    Value typed{};
    if constexpr (std::is_floating_point_v<Value> || std::is_same_v<Value, bool>) {
      typed = static_cast<Value>(value);
    } else {
      auto whole = whole_number<Value>(variable, value);
      if (!whole) return Failure{whole.error()};
      typed = whole.value();
    }
    return check(function, accessors.set(instance_, &reference, 1, &typed, 1));
  }

  template <typename Value>
  Result<double> get_as(const char* function, const Accessors<Value>& accessors, const Variable& variable) {
    const fmi3ValueReference reference = variable.value_reference;
    Value typed{};
    if (auto ok = check(function, accessors.get(instance_, &reference, 1, &typed, 1)); !ok) return Failure{ok.error()};
    return static_cast<double>(typed);
  }

  Fmi3Functions functions_;
  fmi3Instance instance_ = nullptr;
  bool initialized_ = false;
};

template <typename Value, typename Get, typename Set>
Accessors<Value> accessors(Symbols& symbols, const char* get, const char* set) {
  return {symbols.find<Get>(get), symbols.find<Set>(set)};
}

}  // namespace

Result<std::unique_ptr<FmuInstance>> make_fmi3_instance(void* library, const ModelDescription& description,
                                                        const std::filesystem::path& folder, FmuMessages& messages) {
  Symbols symbols{library};
  const Fmi3Functions functions{
      .instantiate = symbols.find<fmi3InstantiateCoSimulationTYPE>("fmi3InstantiateCoSimulation"),
      .free_instance = symbols.find<fmi3FreeInstanceTYPE>("fmi3FreeInstance"),
      .enter_initialization_mode = symbols.find<fmi3EnterInitializationModeTYPE>("fmi3EnterInitializationMode"),
      .exit_initialization_mode = symbols.find<fmi3ExitInitializationModeTYPE>("fmi3ExitInitializationMode"),
      .terminate = symbols.find<fmi3TerminateTYPE>("fmi3Terminate"),
      .do_step = symbols.find<fmi3DoStepTYPE>("fmi3DoStep"),
      .float32 =
          accessors<fmi3Float32, fmi3GetFloat32TYPE, fmi3SetFloat32TYPE>(symbols, "fmi3GetFloat32", "fmi3SetFloat32"),
      .float64 =
          accessors<fmi3Float64, fmi3GetFloat64TYPE, fmi3SetFloat64TYPE>(symbols, "fmi3GetFloat64", "fmi3SetFloat64"),
      .int8 = accessors<fmi3Int8, fmi3GetInt8TYPE, fmi3SetInt8TYPE>(symbols, "fmi3GetInt8", "fmi3SetInt8"),
      .uint8 = accessors<fmi3UInt8, fmi3GetUInt8TYPE, fmi3SetUInt8TYPE>(symbols, "fmi3GetUInt8", "fmi3SetUInt8"),
      .int16 = accessors<fmi3Int16, fmi3GetInt16TYPE, fmi3SetInt16TYPE>(symbols, "fmi3GetInt16", "fmi3SetInt16"),
      .uint16 = accessors<fmi3UInt16, fmi3GetUInt16TYPE, fmi3SetUInt16TYPE>(symbols, "fmi3GetUInt16", "fmi3SetUInt16"),
      .int32 = accessors<fmi3Int32, fmi3GetInt32TYPE, fmi3SetInt32TYPE>(symbols, "fmi3GetInt32", "fmi3SetInt32"),
      .uint32 = accessors<fmi3UInt32, fmi3GetUInt32TYPE, fmi3SetUInt32TYPE>(symbols, "fmi3GetUInt32", "fmi3SetUInt32"),
      .int64 = accessors<fmi3Int64, fmi3GetInt64TYPE, fmi3SetInt64TYPE>(symbols, "fmi3GetInt64", "fmi3SetInt64"),
      .uint64 = accessors<fmi3UInt64, fmi3GetUInt64TYPE, fmi3SetUInt64TYPE>(symbols, "fmi3GetUInt64", "fmi3SetUInt64"),
      .boolean =
          accessors<fmi3Boolean, fmi3GetBooleanTYPE, fmi3SetBooleanTYPE>(symbols, "fmi3GetBoolean", "fmi3SetBoolean")};
  if (!symbols.missing().empty()) return Failure{"the library lacks " + symbols.missing() + ", which duet calls"};
  auto instance = std::make_unique<Fmi3Instance>(functions, messages);
  if (auto made = instance->instantiate(description, folder); !made) return Failure{made.error()};
  return std::unique_ptr<FmuInstance>{std::move(instance)};
}

}  // namespace duet::fmi
