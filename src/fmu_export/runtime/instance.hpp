#pragma once
// One instance of an exported FMU, for the glue of either FMI version: its model storage, inputs and outputs, time,
// and the state machine that refuses calls out of order (docs/FMI.md, "Export"). Nothing is shared between
// instances; the model's code reaches the instance it runs for through a thread-local pointer set around each call.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "fmu_model.hpp"

namespace duet::fmu {

enum class Status { ok, warning, discard, error, fatal };  // numbered as both FMI versions number them

// The importer's logger, reached through the version's glue.
struct Logger {
  void (*log)(const Logger& logger, const char* instance, Status status, const char* category, const char* message);
  void* callback;
  void* environment;
};

enum class Phase { instantiated, initialization, step, terminated };

// The rules that differ between the versions, and their names for the phases.
struct Rules {
  bool get_when_instantiated;  // 3.0 allows reading start values before initialising; 2.0 does not
  const char* phase_names[4];
};

// Which of the model's types one Get or Set function takes: 3.0's are exact, 2.0's Real takes every float.
using TypeSet = std::uint16_t;
constexpr TypeSet types(std::initializer_list<ValueType> list) {
  TypeSet set = 0;
  for (const ValueType type : list) set = static_cast<TypeSet>(set | (1U << static_cast<unsigned>(type)));
  return set;
}

class Instance {
 public:
  Instance(std::string name, Logger logger, bool logging, const Rules& rules);
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;
  ~Instance();

  // The instance whose model runs in this thread now: the hardware port's.
  static Instance* current();

  void set_logging(bool on) { logging_ = on; }
  void log(Status status, const std::string& message) const;
  // Logs "FUNCTION: illegal call sequence in PHASE" and returns Error.
  Status illegal(const char* function) const;
  Status refuse(const char* function, const std::string& reason) const;

  [[nodiscard]] Phase phase() const { return phase_; }
  [[nodiscard]] double time() const { return time_; }

  Status set_start_time(const char* function, double start);  // 2.0's SetupExperiment
  Status enter_initialization(const char* function);
  Status exit_initialization(const char* function);
  Status do_step(const char* function, double point, double size);
  Status terminate(const char* function);
  void reset();

  template <typename T>
  Status get(const char* function, std::span<const std::uint32_t> references, T* values, TypeSet accepted);
  template <typename T>
  Status set(const char* function, std::span<const std::uint32_t> references, const T* values, TypeSet accepted);

  // The hardware port, while this instance's model runs.
  void write_resource(std::string_view name, std::span<const double> values);
  void read_resource(std::string_view name, std::span<double> values) const;

 private:
  class Running;  // binds this instance to its thread for the length of a call into the model

  void initialize_model();
  void tick();
  // The interrupt tasks raised since the last step, each as often as its counter grew, most urgent first; refused,
  // running none, when a counter went back or grew by more than a step may run.
  Status run_raised_interrupts(const char* function);
  // The variable behind a value reference, or null once the problem is logged.
  const VariableSlot* variable(const char* function, std::uint32_t reference, TypeSet accepted) const;
  void* value_address(const VariableSlot& slot);
  [[nodiscard]] bool settable(Role role) const;

  std::string name_;
  Logger logger_;
  bool logging_;
  const Rules& rules_;
  void* storage_;
  std::vector<double> inputs_;
  std::vector<double> outputs_;
  std::vector<std::int32_t> raised_;   // the importer's interrupt counters
  std::vector<std::int32_t> handled_;  // what the steps have run of them
  Phase phase_ = Phase::instantiated;
  double period_s_;
  double start_s_ = 0;
  double time_ = 0;
  std::uint64_t ticks_ = 0;
  bool set_since_step_ = false;  // a Set in step mode: a Get must wait for the next step
};

namespace detail {

template <typename Stored, typename T>
bool store_as(void* at, T value) {
  if constexpr (std::is_same_v<T, bool>) {
    *static_cast<Stored*>(at) = static_cast<Stored>(value);
  } else if constexpr (std::is_same_v<Stored, bool>) {
    *static_cast<bool*>(at) = value != T{};
  } else if constexpr (std::is_floating_point_v<Stored>) {
    *static_cast<Stored*>(at) = static_cast<Stored>(value);
  } else if constexpr (std::is_floating_point_v<T>) {  // 2.0's Real into an integer: only a whole number that fits
    if (!(value == std::trunc(value)) || value < static_cast<T>(std::numeric_limits<Stored>::min()) ||
        value > static_cast<T>(std::numeric_limits<Stored>::max())) {
      return false;
    }
    *static_cast<Stored*>(at) = static_cast<Stored>(value);
  } else {
    if (!std::in_range<Stored>(value)) return false;
    *static_cast<Stored*>(at) = static_cast<Stored>(value);
  }
  return true;
}

template <typename Stored, typename T>
T load_as(const void* at) {
  return static_cast<T>(*static_cast<const Stored*>(at));
}

// Calls `action.template operator()<Stored>()` with the C++ type the model stores `type` as.
template <typename Action>
decltype(auto) with_stored_type(ValueType type, Action&& action) {
  switch (type) {
    case ValueType::float64: return action.template operator()<double>();
    case ValueType::float32: return action.template operator()<float>();
    case ValueType::int8: return action.template operator()<std::int8_t>();
    case ValueType::int16: return action.template operator()<std::int16_t>();
    case ValueType::int32: return action.template operator()<std::int32_t>();
    case ValueType::uint8: return action.template operator()<std::uint8_t>();
    case ValueType::uint16: return action.template operator()<std::uint16_t>();
    case ValueType::uint32: return action.template operator()<std::uint32_t>();
    case ValueType::boolean: break;
  }
  return action.template operator()<bool>();
}

}  // namespace detail

template <typename T>
Status Instance::get(const char* function, std::span<const std::uint32_t> references, T* values, TypeSet accepted) {
  const bool allowed = phase_ != Phase::instantiated || rules_.get_when_instantiated;
  if (!allowed) return illegal(function);
  if (phase_ == Phase::step && set_since_step_) {
    return refuse(function, "illegal call sequence: a Get after a Set needs a step in between");
  }
  for (std::size_t k = 0; k < references.size(); ++k) {
    const VariableSlot* slot = variable(function, references[k], accepted);
    if (slot == nullptr) return Status::error;
    const void* at = value_address(*slot);
    values[k] =
        detail::with_stored_type(slot->type, [at]<typename Stored>() { return detail::load_as<Stored, T>(at); });
  }
  return Status::ok;
}

template <typename T>
Status Instance::set(const char* function, std::span<const std::uint32_t> references, const T* values,
                     TypeSet accepted) {
  if (phase_ == Phase::terminated) return illegal(function);
  for (std::size_t k = 0; k < references.size(); ++k) {
    const VariableSlot* slot = variable(function, references[k], accepted);
    if (slot == nullptr) return Status::error;
    if (!settable(slot->role)) {
      const bool fixed_too_late = slot->role == Role::fixed_parameter;
      return refuse(function, std::string{fixed_too_late ? "illegal call sequence: " : ""} + "variable '" + slot->name +
                                  "' (" + std::to_string(references[k]) + ") " +
                                  (fixed_too_late ? "is a fixed parameter, set only before initialisation ends"
                                                  : "cannot be set"));
    }
    void* at = value_address(*slot);
    const T value = values[k];
    const bool stored = detail::with_stored_type(
        slot->type, [at, value]<typename Stored>() { return detail::store_as<Stored>(at, value); });
    if (!stored) {
      return refuse(function, "the value for '" + std::string{slot->name} + "' does not fit its type");
    }
  }
  if (phase_ == Phase::step && !references.empty()) set_since_step_ = true;
  return Status::ok;
}

}  // namespace duet::fmu
