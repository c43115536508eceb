#pragma once
// What duet knows of an FMU from its modelDescription.xml: the parts of FMI 2.0 and 3.0 that an importer of a
// co-simulation FMU needs and that duet's exporter writes (docs/FMI.md). One data model for both versions; where
// they differ (types, the token's name) the version says which applies.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace duet::fmi {

enum class FmiVersion { v2, v3 };

// 2.0's types, then 3.0's (Boolean, String and Enumeration are in both; the version tells them apart).
enum class VariableType {
  real,
  integer,
  boolean,
  string,
  enumeration,
  float32,
  float64,
  int8,
  uint8,
  int16,
  uint16,
  int32,
  uint32,
  int64,
  uint64,
  binary,
  clock
};
enum class Causality { parameter, calculated_parameter, structural_parameter, input, output, local, independent };
enum class Variability { constant, fixed, tunable, discrete, continuous };
enum class Initial { none, exact, approx, calculated };  // none: the variable may not have one (inputs in 2.0, time)

// The spelling in modelDescription.xml: "Float64", "calculatedParameter", "tunable", "exact" ("" for none).
[[nodiscard]] std::string_view xml_name(VariableType type);
[[nodiscard]] std::string_view xml_name(Causality causality);
[[nodiscard]] std::string_view xml_name(Variability variability);
[[nodiscard]] std::string_view xml_name(Initial initial);
[[nodiscard]] bool is_float(VariableType type);  // Real, Float32, Float64: the only types that may be continuous

struct Variable {
  std::string name;
  std::uint32_t value_reference = 0;
  VariableType type = VariableType::float64;
  Causality causality = Causality::local;
  Variability variability = Variability::continuous;
  Initial initial = Initial::none;   // the standard's default applied when the file has none
  std::optional<std::string> start;  // as written; several values separated by spaces for arrays
  std::string unit;
  std::string description;
  bool operator==(const Variable&) const = default;
};

struct CoSimulation {
  std::string model_identifier;  // a C identifier: the shared library's name without .so
  bool can_handle_variable_communication_step_size = false;
  bool can_be_instantiated_only_once_per_process = false;
  bool needs_execution_tool = false;
  std::optional<double> fixed_internal_step_size;  // 3.0 only
  bool operator==(const CoSimulation&) const = default;
};

struct DefaultExperiment {
  std::optional<double> start_time;
  std::optional<double> stop_time;
  std::optional<double> tolerance;
  std::optional<double> step_size;
  bool operator==(const DefaultExperiment&) const = default;
};

struct ModelDescription {
  FmiVersion version = FmiVersion::v3;
  std::string model_name;
  std::string token;  // 2.0's guid, 3.0's instantiationToken: handed to the FMU when instantiating
  std::string description;
  std::string generation_tool;
  CoSimulation co_simulation;
  std::optional<DefaultExperiment> default_experiment;
  std::vector<std::string> units;  // UnitDefinitions' names
  std::vector<Variable> variables;
  std::vector<std::size_t> outputs;  // ModelStructure's outputs, as indices into `variables`, in its order
  bool operator==(const ModelDescription&) const = default;
};

}  // namespace duet::fmi
