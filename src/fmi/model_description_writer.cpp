#include "duet/fmi/model_description_writer.hpp"

#include <pugixml.hpp>

#include <sstream>

#include "duet/support/number_text.hpp"

namespace duet::fmi {
namespace {

struct Unwritable {
  std::string message;
};

// The shortest text that reads back as the same double.
void set(pugi::xml_node node, const char* attribute, std::string_view value) {
  node.append_attribute(attribute).set_value(std::string{value}.c_str());
}
void set_if(pugi::xml_node node, const char* attribute, bool value) {
  if (value) set(node, attribute, "true");
}
void set_if(pugi::xml_node node, const char* attribute, const std::optional<double>& value) {
  if (value) set(node, attribute, shortest_text(*value));
}
void set_if(pugi::xml_node node, const char* attribute, const std::string& value) {
  if (!value.empty()) set(node, attribute, value);
}

bool type_of_version(VariableType type, FmiVersion version) {
  const bool in_both = type == VariableType::boolean || type == VariableType::string;
  const bool fmi2 = type == VariableType::real || type == VariableType::integer;
  return in_both || (version == FmiVersion::v2 ? fmi2 : !fmi2);
}

void write_variable(pugi::xml_node list, const Variable& variable, FmiVersion version) {
  const std::string quoted = "variable \"" + variable.name + "\": ";
  if (variable.type == VariableType::enumeration)
    throw Unwritable{quoted + "enumerations need type definitions, which duet does not write"};
  if (variable.type == VariableType::clock) throw Unwritable{quoted + "duet does not write clocks"};
  if (!type_of_version(variable.type, version))
    throw Unwritable{quoted + std::string{xml_name(variable.type)} + " is not a type of FMI " +
                     (version == FmiVersion::v2 ? "2.0" : "3.0")};
  pugi::xml_node element =
      list.append_child(version == FmiVersion::v2 ? "ScalarVariable" : std::string{xml_name(variable.type)}.c_str());
  set(element, "name", variable.name);
  set(element, "valueReference", std::to_string(variable.value_reference));
  set_if(element, "description", variable.description);
  set(element, "causality", xml_name(variable.causality));
  set(element, "variability", xml_name(variable.variability));
  set_if(element, "initial", std::string{xml_name(variable.initial)});
  pugi::xml_node typed =
      version == FmiVersion::v2 ? element.append_child(std::string{xml_name(variable.type)}.c_str()) : element;
  const bool start_as_child =
      version == FmiVersion::v3 && (variable.type == VariableType::string || variable.type == VariableType::binary);
  if (variable.start && start_as_child) set(typed.append_child("Start"), "value", *variable.start);
  if (variable.start && !start_as_child) set(typed, "start", *variable.start);
  if (is_float(variable.type)) set_if(typed, "unit", variable.unit);
}

// What the importer may ask for during initialisation: outputs that are computed, and calculated parameters.
bool initial_unknown(const Variable& variable) {
  return (variable.causality == Causality::output &&
          (variable.initial == Initial::approx || variable.initial == Initial::calculated)) ||
         variable.causality == Causality::calculated_parameter;
}

void write_structure(pugi::xml_node root, const ModelDescription& description) {
  pugi::xml_node structure = root.append_child("ModelStructure");
  const auto& variables = description.variables;
  if (description.version == FmiVersion::v2) {
    auto list = [&](const char* name, const std::vector<std::size_t>& indices) {
      if (indices.empty()) return;  // a list that is there has entries
      pugi::xml_node element = structure.append_child(name);
      for (const std::size_t index : indices) set(element.append_child("Unknown"), "index", std::to_string(index + 1));
    };
    std::vector<std::size_t> unknowns;
    for (std::size_t index = 0; index < variables.size(); ++index)
      if (initial_unknown(variables[index])) unknowns.push_back(index);
    list("Outputs", description.outputs);
    list("InitialUnknowns", unknowns);
    return;
  }
  for (const std::size_t index : description.outputs)
    set(structure.append_child("Output"), "valueReference", std::to_string(variables[index].value_reference));
  for (const Variable& variable : variables)
    if (initial_unknown(variable))
      set(structure.append_child("InitialUnknown"), "valueReference", std::to_string(variable.value_reference));
}

std::string write(const ModelDescription& description) {
  const bool v2 = description.version == FmiVersion::v2;
  pugi::xml_document document;
  pugi::xml_node declaration = document.append_child(pugi::node_declaration);
  set(declaration, "version", "1.0");
  set(declaration, "encoding", "UTF-8");
  pugi::xml_node root = document.append_child("fmiModelDescription");
  set(root, "fmiVersion", v2 ? "2.0" : "3.0");
  set(root, "modelName", description.model_name);
  set(root, v2 ? "guid" : "instantiationToken", description.token);
  set_if(root, "description", description.description);
  set_if(root, "generationTool", description.generation_tool);
  // Flat: duet's names ("gpio:LED0" of a resource, "x[0]" of an element) are plain strings, not the structured
  // convention's paths.
  set(root, "variableNamingConvention", "flat");

  const CoSimulation& co_simulation = description.co_simulation;
  pugi::xml_node element = root.append_child("CoSimulation");
  set(element, "modelIdentifier", co_simulation.model_identifier);
  set_if(element, "needsExecutionTool", co_simulation.needs_execution_tool);
  set_if(element, "canHandleVariableCommunicationStepSize", co_simulation.can_handle_variable_communication_step_size);
  set_if(element, "canBeInstantiatedOnlyOncePerProcess", co_simulation.can_be_instantiated_only_once_per_process);
  if (!v2) set_if(element, "fixedInternalStepSize", co_simulation.fixed_internal_step_size);

  if (!description.units.empty()) {
    pugi::xml_node units = root.append_child("UnitDefinitions");
    for (const std::string& unit : description.units) set(units.append_child("Unit"), "name", unit);
  }
  if (const auto& experiment = description.default_experiment) {
    pugi::xml_node defaults = root.append_child("DefaultExperiment");
    set_if(defaults, "startTime", experiment->start_time);
    set_if(defaults, "stopTime", experiment->stop_time);
    set_if(defaults, "tolerance", experiment->tolerance);
    set_if(defaults, "stepSize", experiment->step_size);
  }
  pugi::xml_node variables = root.append_child("ModelVariables");
  for (const Variable& variable : description.variables) write_variable(variables, variable, description.version);
  write_structure(root, description);

  std::ostringstream text;
  document.save(text, "  ", pugi::format_default, pugi::encoding_utf8);
  return text.str();
}

}  // namespace

Result<std::string> write_model_description(const ModelDescription& description) {
  try {
    return write(description);
  } catch (const Unwritable& problem) {
    return Failure{problem.message};
  }
}

}  // namespace duet::fmi
