#include "duet/fmu_export/fmu_interface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "duet/model/data_type.hpp"
#include "duet/model/interpreter.hpp"
#include "duet/support/number_text.hpp"
#include "duet/version.hpp"

namespace duet::fmu_export {
namespace {

using fmi::Causality;
using fmi::Initial;
using fmi::Variability;
using fmi::VariableType;
using model::DataType;

VariableType fmi_type(DataType type, fmi::FmiVersion version) {
  if (version == fmi::FmiVersion::v2) {
    switch (type) {
      case DataType::float64:
      case DataType::float32:
      case DataType::uint32: return VariableType::real;  // 2.0's Integer is 32-bit signed
      case DataType::boolean: return VariableType::boolean;
      default: return VariableType::integer;
    }
  }
  switch (type) {
    case DataType::float64: return VariableType::float64;
    case DataType::float32: return VariableType::float32;
    case DataType::int8: return VariableType::int8;
    case DataType::int16: return VariableType::int16;
    case DataType::int32: return VariableType::int32;
    case DataType::uint8: return VariableType::uint8;
    case DataType::uint16: return VariableType::uint16;
    case DataType::uint32: return VariableType::uint32;
    case DataType::boolean: break;
  }
  return VariableType::boolean;
}

std::string start_text(DataType type, double value) {
  if (type == DataType::boolean) return value != 0 ? "true" : "false";
  return shortest_text(value);
}

std::string element_name(const std::string& name, std::size_t element, std::size_t count) {
  return count == 1 ? name : name + "[" + std::to_string(element) + "]";
}

// The values one hardware block exchanges with its resource, as the host port and `duet sim` count them: what it
// writes (its inputs' elements; an AdcStart the sample count) and what it reads (its outputs' elements; an input
// capture always both the count and the edge).
struct Exchange {
  std::size_t written = 0;
  std::size_t read = 0;
};
Exchange exchange(const model::Program& program, const model::ProgramBlock& block) {
  Exchange values;
  for (const std::size_t signal : block.inputs) values.written += program.signals[signal].type.elements();
  for (const std::size_t signal : block.outputs) values.read += program.signals[signal].type.elements();
  if (block.type() == "AdcStart") values.written = 1;
  if (block.type() == "InputCapture") values.read = 2;
  return values;
}

// Which parameters a task reads: the others only the initialisation reads (constant blocks), if anything.
std::vector<bool> read_by_tasks(const model::Program& program) {
  std::vector<bool> read(program.model->parameters.size(), false);
  for (const model::ProgramBlock& block : program.blocks) {
    if (block.task == model::at_initialisation) continue;
    for (const auto& [name, argument] : block.arguments) {
      if (argument.kind == model::Argument::Kind::parameter) read[argument.parameter] = true;
    }
    std::vector<std::size_t> signals = block.inputs;
    signals.insert(signals.end(), block.enables.begin(), block.enables.end());
    for (const std::size_t signal : signals) {
      if (const auto parameter = program.signals[signal].parameter) read[*parameter] = true;
    }
  }
  return read;
}

class Builder {
 public:
  Builder(const model::Program& program, fmi::FmiVersion version) : program_(program), version_(version) {}

  FmuInterface build() {
    const double period_s = program_.model->base_period_us * 1e-6;
    fmi::ModelDescription& description = result_.description;
    description.version = version_;
    description.model_name = program_.model->name;
    description.description = program_.model->description;
    description.generation_tool = "duet " + std::string{duet::version};
    description.co_simulation = {
        .model_identifier = program_.model->name,
        .can_handle_variable_communication_step_size = true,
        .can_be_instantiated_only_once_per_process = false,
        .needs_execution_tool = false,
        .fixed_internal_step_size = version_ == fmi::FmiVersion::v3 ? std::optional{period_s} : std::nullopt};
    description.default_experiment = fmi::DefaultExperiment{.start_time = 0.0, .step_size = period_s};
    add({.name = "time",
         .type = fmi_type(DataType::float64, version_),
         .causality = Causality::independent,
         .variability = Variability::continuous,
         .unit = "s",
         .description = "simulation time"},
        {.role = Role::time});
    add_resources();
    add_interrupts();
    add_parameters();
    add_signals();
    for (const fmi::Variable& variable : description.variables) {
      if (!fmi::is_float(variable.type)) continue;  // the standard gives units to floats only
      const bool listed =
          std::find(description.units.begin(), description.units.end(), variable.unit) != description.units.end();
      if (!variable.unit.empty() && !listed) description.units.push_back(variable.unit);
    }
    return std::move(result_);
  }

 private:
  void add(fmi::Variable variable, Binding binding) {
    variable.value_reference = static_cast<std::uint32_t>(result_.description.variables.size());
    if (variable.causality == Causality::output) {
      result_.description.outputs.push_back(result_.description.variables.size());
    }
    result_.description.variables.push_back(std::move(variable));
    result_.bindings.push_back(std::move(binding));
  }

  // One variable per value a resource holds; a resource the model both reads and writes (a SPI bus) has both, named
  // apart by ".read" and ".written".
  void add_resources() {
    struct Use {
      std::size_t count = 0;
      std::string blocks;
    };
    std::vector<std::pair<std::string, bool>> order;  // (resource, read), as the blocks first use them
    std::map<std::pair<std::string, bool>, Use> uses;
    for (const model::ProgramBlock& block : program_.blocks) {
      const std::string resource = model::hardware_resource(block);
      if (resource.empty()) continue;
      const Exchange values = exchange(program_, block);
      for (const auto& [read, count] : {std::pair{false, values.written}, std::pair{true, values.read}}) {
        if (count == 0) continue;
        const std::pair key{resource, read};
        if (uses.count(key) == 0) order.push_back(key);
        Use& use = uses[key];
        use.count = std::max(use.count, count);
        use.blocks += (use.blocks.empty() ? "" : ", ") + block.path + " (" + block.type() + ")";
      }
    }
    for (const bool read : {true, false}) {
      for (const auto& key : order) {
        if (key.second != read) continue;
        const Use& use = uses.at(key);
        const bool both_ways = uses.count({key.first, !read}) != 0;
        const std::string name = key.first + (both_ways ? (read ? ".read" : ".written") : "");
        std::size_t& used = read ? result_.inputs : result_.outputs;
        result_.resources.push_back({key.first, read, used, use.count});
        for (std::size_t element = 0; element < use.count; ++element) {
          fmi::Variable variable{.name = element_name(name, element, use.count),
                                 .type = fmi_type(DataType::float64, version_),
                                 .causality = read ? Causality::input : Causality::output,
                                 .variability = Variability::discrete,
                                 .description = key.first + (read ? ", read by " : ", written by ") + use.blocks};
          if (read) {
            variable.initial = version_ == fmi::FmiVersion::v3 ? Initial::exact : Initial::none;
            variable.start = "0";
          } else {
            variable.initial = Initial::calculated;
          }
          add(std::move(variable), {.role = read ? Role::input : Role::output, .index = used++});
        }
      }
    }
  }

  // A counter per interrupt that triggers a task: the importer raises the interrupt by counting it up.
  void add_interrupts() {
    for (std::size_t task = 0; task < program_.tasks.size(); ++task) {
      const model::ProgramTask& triggered = program_.tasks[task];
      if (triggered.rate.kind != model::Rate::Kind::interrupt) continue;
      std::vector<std::string>& names = result_.interrupts;
      const auto known = std::find(names.begin(), names.end(), triggered.rate.interrupt);
      const std::size_t counter = static_cast<std::size_t>(known - names.begin());
      result_.interrupt_tasks.push_back({.counter = counter, .task = task});
      if (known != names.end()) continue;
      names.push_back(triggered.rate.interrupt);
      add({.name = "interrupt:" + triggered.rate.interrupt,
           .type = fmi_type(DataType::int32, version_),
           .causality = Causality::input,
           .variability = Variability::discrete,
           .initial = version_ == fmi::FmiVersion::v3 ? Initial::exact : Initial::none,
           .start = "0",
           .description = "how often interrupt " + triggered.rate.interrupt +
                          " was raised: each increment runs its task(s) once at the start of the next step"},
          {.role = Role::interrupt_count, .type = DataType::int32, .index = counter});
    }
  }

  void add_parameters() {
    const std::vector<bool> tunable = read_by_tasks(program_);
    for (std::size_t index = 0; index < program_.model->parameters.size(); ++index) {
      const model::Parameter& parameter = program_.model->parameters[index];
      const std::size_t count = parameter.value.elements.size();
      for (std::size_t element = 0; element < count; ++element) {
        add({.name = element_name(parameter.name, element, count),
             .type = fmi_type(parameter.type, version_),
             .causality = Causality::parameter,
             .variability = tunable[index] ? Variability::tunable : Variability::fixed,
             .initial = Initial::exact,
             .start = start_text(parameter.type, parameter.value.elements[element]),
             .unit = parameter.unit,
             .description = parameter.description},
            {.role = tunable[index] ? Role::tunable_parameter : Role::fixed_parameter,
             .type = parameter.type,
             .member = "parameters." + parameter.name + (count == 1 ? "" : "[" + std::to_string(element) + "]")});
      }
    }
  }

  void add_signals() {
    for (const model::ProgramSignal& signal : program_.signals) {
      if (!signal.measurable) continue;
      const std::size_t count = signal.type.elements();
      for (std::size_t element = 0; element < count; ++element) {
        add({.name = element_name(signal.name, element, count),
             .type = fmi_type(signal.type.type, version_),
             .causality = Causality::local,
             .variability = Variability::discrete,  // it changes at the model's ticks only
             .initial = Initial::calculated,
             .unit = signal.unit,
             .description = signal.description},
            {.role = Role::local,
             .type = signal.type.type,
             .member =
                 "memory.signals." + signal.identifier + (count == 1 ? "" : "[" + std::to_string(element) + "]")});
      }
    }
  }

  const model::Program& program_;
  fmi::FmiVersion version_;
  FmuInterface result_;
};

}  // namespace

FmuInterface fmu_interface(const model::Program& program, fmi::FmiVersion version) {
  return Builder{program, version}.build();
}

}  // namespace duet::fmu_export
