#include "duet/fmi/model_description_reader.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <utility>

namespace duet::fmi {
namespace {

struct Problem {
  std::string message;
};

template <typename Value>
using Choices = std::vector<std::pair<std::string_view, Value>>;

const Choices<VariableType> fmi2_types = {{"Real", VariableType::real},
                                          {"Integer", VariableType::integer},
                                          {"Boolean", VariableType::boolean},
                                          {"String", VariableType::string},
                                          {"Enumeration", VariableType::enumeration}};
const Choices<VariableType> fmi3_types = {
    {"Float32", VariableType::float32}, {"Float64", VariableType::float64},
    {"Int8", VariableType::int8},       {"UInt8", VariableType::uint8},
    {"Int16", VariableType::int16},     {"UInt16", VariableType::uint16},
    {"Int32", VariableType::int32},     {"UInt32", VariableType::uint32},
    {"Int64", VariableType::int64},     {"UInt64", VariableType::uint64},
    {"Boolean", VariableType::boolean}, {"String", VariableType::string},
    {"Binary", VariableType::binary},   {"Enumeration", VariableType::enumeration},
    {"Clock", VariableType::clock}};

Choices<Causality> causalities(FmiVersion version) {
  Choices<Causality> choices = {
      {"parameter", Causality::parameter}, {"calculatedParameter", Causality::calculated_parameter},
      {"input", Causality::input},         {"output", Causality::output},
      {"local", Causality::local},         {"independent", Causality::independent}};
  if (version == FmiVersion::v3) choices.emplace_back("structuralParameter", Causality::structural_parameter);
  return choices;
}
const Choices<Variability> variabilities = {{"constant", Variability::constant},
                                            {"fixed", Variability::fixed},
                                            {"tunable", Variability::tunable},
                                            {"discrete", Variability::discrete},
                                            {"continuous", Variability::continuous}};
const Choices<Initial> initials = {
    {"exact", Initial::exact}, {"approx", Initial::approx}, {"calculated", Initial::calculated}};

bool is_c_identifier(std::string_view text) {
  auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  return !text.empty() && letter(text.front()) &&
         std::all_of(text.begin(), text.end(), [&](char c) { return letter(c) || (c >= '0' && c <= '9'); });
}

bool variability_allowed(Causality causality, Variability variability) {
  switch (causality) {
    case Causality::parameter:
    case Causality::calculated_parameter:
    case Causality::structural_parameter:
      return variability == Variability::fixed || variability == Variability::tunable;
    case Causality::input: return variability == Variability::discrete || variability == Variability::continuous;
    case Causality::output: return variability != Variability::fixed && variability != Variability::tunable;
    case Causality::local: return true;
    case Causality::independent: return variability == Variability::continuous;
  }
  return false;
}

// The standard's default variability: 2.0 continuous for all; 3.0 fixed for parameters, continuous for floats,
// discrete for the rest.
Variability default_variability(FmiVersion version, Causality causality, VariableType type) {
  if (version == FmiVersion::v2) return Variability::continuous;
  if (causality == Causality::parameter || causality == Causality::calculated_parameter ||
      causality == Causality::structural_parameter)
    return Variability::fixed;
  return is_float(type) ? Variability::continuous : Variability::discrete;
}

Initial default_initial(FmiVersion version, Causality causality, Variability variability) {
  switch (causality) {
    case Causality::parameter:
    case Causality::structural_parameter: return Initial::exact;
    case Causality::calculated_parameter: return Initial::calculated;
    case Causality::input: return version == FmiVersion::v3 ? Initial::exact : Initial::none;
    case Causality::independent: return Initial::none;
    case Causality::output:
    case Causality::local: return variability == Variability::constant ? Initial::exact : Initial::calculated;
  }
  return Initial::none;
}

// 2.0 value references are unique per base type: Enumeration shares Integer's.
VariableType base_type(VariableType type) { return type == VariableType::enumeration ? VariableType::integer : type; }

class DescriptionReader {
 public:
  explicit DescriptionReader(std::string_view xml) : xml_(xml) {}

  ModelDescription read() {
    pugi::xml_document document;
    const pugi::xml_parse_result parsed =
        document.load_buffer(xml_.data(), xml_.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed) refuse_at(parsed.offset, std::string{"not well-formed XML: "} + parsed.description());
    const pugi::xml_node root = document.document_element();
    if (std::string_view{root.name()} != "fmiModelDescription")
      refuse(root, "the root element is <" + std::string{root.name()} + ">, not <fmiModelDescription>");
    ModelDescription description;
    const std::string version = required(root, "fmiVersion");
    if (version == "2.0")
      description.version = FmiVersion::v2;
    else if (version == "3.0")
      description.version = FmiVersion::v3;
    else
      refuse(root, "fmiVersion \"" + version + "\" is neither 2.0 nor 3.0");
    version_ = description.version;
    description.model_name = required(root, "modelName");
    description.token = required(root, version_ == FmiVersion::v2 ? "guid" : "instantiationToken");
    description.description = root.attribute("description").value();
    description.generation_tool = root.attribute("generationTool").value();
    description.co_simulation = co_simulation(root);
    if (const pugi::xml_node units = root.child("UnitDefinitions")) description.units = unit_names(units);
    if (const pugi::xml_node experiment = root.child("DefaultExperiment"))
      description.default_experiment = default_experiment(experiment);
    const pugi::xml_node variables = root.child("ModelVariables");
    if (!variables) refuse(root, "no <ModelVariables> element");
    read_variables(variables, description.variables);
    const pugi::xml_node structure = root.child("ModelStructure");
    if (!structure) refuse(root, "no <ModelStructure> element");
    description.outputs = outputs(structure, description.variables);
    return description;
  }

 private:
  // pugixml knows where a node starts in the text; a line is one more than the newlines before it.
  std::string line_at(std::ptrdiff_t offset) const {
    const std::ptrdiff_t end = std::clamp<std::ptrdiff_t>(offset, 0, std::ssize(xml_));
    return std::to_string(1 + std::count(xml_.begin(), xml_.begin() + end, '\n'));
  }
  std::string line(pugi::xml_node node) const { return line_at(node.offset_debug()); }
  [[noreturn]] void refuse_at(std::ptrdiff_t offset, const std::string& problem) const {
    throw Problem{"modelDescription.xml:" + line_at(offset) + ": " + problem};
  }
  [[noreturn]] void refuse(pugi::xml_node node, const std::string& problem) const {
    refuse_at(node.offset_debug(), problem);
  }

  std::string required(pugi::xml_node node, const char* attribute) const {
    const pugi::xml_attribute found = node.attribute(attribute);
    if (!found) refuse(node, "<" + std::string{node.name()} + "> has no " + attribute + " attribute");
    return found.value();
  }

  template <typename Value>
  std::optional<Value> choice(pugi::xml_node node, const char* attribute, const Choices<Value>& choices) const {
    const pugi::xml_attribute found = node.attribute(attribute);
    if (!found) return std::nullopt;
    for (const auto& [name, value] : choices)
      if (name == found.value()) return value;
    std::string names;
    for (const auto& each : choices) names += (names.empty() ? "" : ", ") + std::string{each.first};
    refuse(node, std::string{attribute} + " \"" + found.value() + "\" is not one of " + names);
  }

  bool boolean(pugi::xml_node node, const char* attribute) const {
    const std::string_view text = node.attribute(attribute).value();
    if (text.empty() || text == "false" || text == "0") return false;
    if (text == "true" || text == "1") return true;
    refuse(node, std::string{attribute} + " \"" + std::string{text} + "\" is not true or false");
  }

  template <typename Number>
  std::optional<Number> number(pugi::xml_node node, const char* attribute) const {
    const pugi::xml_attribute found = node.attribute(attribute);
    if (!found) return std::nullopt;
    const std::string_view text = found.value();
    Number value{};
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    bool finite = true;
    if constexpr (std::is_floating_point_v<Number>) finite = std::isfinite(value);
    if (error != std::errc{} || end != text.data() + text.size() || text.empty() || !finite)
      refuse(node, std::string{attribute} + " \"" + std::string{text} + "\" is not " +
                       (std::is_floating_point_v<Number> ? "a finite number" : "an unsigned integer"));
    return value;
  }

  std::uint32_t required_number(pugi::xml_node node, const char* attribute) const {
    (void)required(node, attribute);
    return *number<std::uint32_t>(node, attribute);
  }

  CoSimulation co_simulation(pugi::xml_node root) const {
    const pugi::xml_node element = root.child("CoSimulation");
    if (!element) refuse(root, "no <CoSimulation> element: duet runs co-simulation FMUs only");
    CoSimulation co_simulation;
    co_simulation.model_identifier = required(element, "modelIdentifier");
    if (!is_c_identifier(co_simulation.model_identifier))
      refuse(element, "modelIdentifier \"" + co_simulation.model_identifier +
                          "\" is not a C identifier (it names the shared library and its functions)");
    co_simulation.can_handle_variable_communication_step_size =
        boolean(element, "canHandleVariableCommunicationStepSize");
    co_simulation.can_be_instantiated_only_once_per_process = boolean(element, "canBeInstantiatedOnlyOncePerProcess");
    co_simulation.needs_execution_tool = boolean(element, "needsExecutionTool");
    if (version_ == FmiVersion::v3) {
      co_simulation.fixed_internal_step_size = number<double>(element, "fixedInternalStepSize");
      if (co_simulation.fixed_internal_step_size && !(*co_simulation.fixed_internal_step_size > 0))
        refuse(element, "fixedInternalStepSize must be greater than 0");
    }
    return co_simulation;
  }

  std::vector<std::string> unit_names(pugi::xml_node definitions) const {
    std::vector<std::string> names;
    for (const pugi::xml_node unit : definitions.children("Unit")) names.push_back(required(unit, "name"));
    if (names.empty()) refuse(definitions, "<UnitDefinitions> lists no <Unit>");
    return names;
  }

  DefaultExperiment default_experiment(pugi::xml_node element) const {
    DefaultExperiment experiment{.start_time = number<double>(element, "startTime"),
                                 .stop_time = number<double>(element, "stopTime"),
                                 .tolerance = number<double>(element, "tolerance"),
                                 .step_size = number<double>(element, "stepSize")};
    if (experiment.start_time && experiment.stop_time && *experiment.stop_time < *experiment.start_time)
      refuse(element, "stopTime is before startTime");
    if (experiment.step_size && !(*experiment.step_size > 0)) refuse(element, "stepSize must be greater than 0");
    return experiment;
  }

  // The element that holds the type's attributes (start, unit): 2.0's only child of <ScalarVariable>, 3.0's
  // variable element itself.
  pugi::xml_node typed_element(pugi::xml_node variable, const std::string& name, VariableType& type) const {
    if (version_ == FmiVersion::v3) {
      const auto found = std::find_if(fmi3_types.begin(), fmi3_types.end(),
                                      [&](const auto& each) { return each.first == variable.name(); });
      if (found == fmi3_types.end())
        refuse(variable, "<" + std::string{variable.name()} + "> is not a variable type of FMI 3.0");
      type = found->second;
      return variable;
    }
    if (std::string_view{variable.name()} != "ScalarVariable")
      refuse(variable, "<" + std::string{variable.name()} + "> in <ModelVariables> (FMI 2.0 has <ScalarVariable>)");
    pugi::xml_node typed;
    for (const pugi::xml_node child : variable.children()) {
      const auto found = std::find_if(fmi2_types.begin(), fmi2_types.end(),
                                      [&](const auto& each) { return each.first == child.name(); });
      if (found == fmi2_types.end()) continue;
      if (typed) refuse(child, "\"" + name + "\" has two type elements");
      typed = child;
      type = found->second;
    }
    if (!typed) refuse(variable, "\"" + name + "\" has no type element (Real, Integer, Boolean, String, Enumeration)");
    return typed;
  }

  static std::optional<std::string> start_value(pugi::xml_node typed, VariableType type) {
    if (const pugi::xml_attribute start = typed.attribute("start")) return std::string{start.value()};
    if (type != VariableType::string && type != VariableType::binary) return std::nullopt;
    std::optional<std::string> values;  // 3.0's String and Binary hold theirs in <Start value=…/> children
    for (const pugi::xml_node start : typed.children("Start"))
      values = (values ? *values + " " : std::string{}) + start.attribute("value").value();
    return values;
  }

  Variable variable(pugi::xml_node element) const {
    Variable variable;
    variable.name = required(element, "name");
    variable.value_reference = required_number(element, "valueReference");
    variable.description = element.attribute("description").value();
    const pugi::xml_node typed = typed_element(element, variable.name, variable.type);
    if (variable.type == VariableType::enumeration) (void)required(typed, "declaredType");
    variable.causality = choice(element, "causality", causalities(version_)).value_or(Causality::local);
    const auto variability = choice(element, "variability", variabilities);
    variable.variability = variability.value_or(default_variability(version_, variable.causality, variable.type));
    const auto initial = choice(element, "initial", initials);
    variable.initial = initial.value_or(default_initial(version_, variable.causality, variable.variability));
    variable.start = start_value(typed, variable.type);
    if (is_float(variable.type)) variable.unit = typed.attribute("unit").value();
    check(element, variable, variability.has_value(), initial.has_value());
    return variable;
  }

  void check(pugi::xml_node element, const Variable& variable, bool variability_given, bool initial_given) const {
    const std::string quoted = "\"" + variable.name + "\"";
    const std::string causality{xml_name(variable.causality)};
    if (!variability_allowed(variable.causality, variable.variability))
      refuse(element, quoted + ": causality " + causality + " cannot have variability " +
                          std::string{xml_name(variable.variability)});
    if (variable.variability == Variability::continuous && !is_float(variable.type))
      refuse(element, quoted + ": " + std::string{xml_name(variable.type)} + " variables cannot be continuous" +
                          (variability_given ? "" : " (the default; say variability=\"discrete\")"));
    if (initial_given && variable.causality == Causality::independent)
      refuse(element, quoted + ": the independent variable has no initial attribute");
    if (initial_given && variable.causality == Causality::input && version_ == FmiVersion::v2)
      refuse(element, quoted + ": an input has no initial attribute in FMI 2.0");
    if (variable.causality == Causality::input && version_ == FmiVersion::v3 && variable.initial != Initial::exact)
      refuse(element, quoted + ": an input's initial can only be exact");
    if (variable.causality == Causality::independent) {
      if (!is_float(variable.type)) refuse(element, quoted + ": the independent variable must be a floating-point one");
      if (variable.start) refuse(element, quoted + ": the independent variable may not have a start value");
      return;
    }
    std::string needs_start_because;
    if (variable.causality == Causality::input || variable.causality == Causality::parameter ||
        variable.causality == Causality::structural_parameter)
      needs_start_because = "causality " + causality;
    else if (variable.variability == Variability::constant)
      needs_start_because = "variability constant";
    else if (variable.initial == Initial::exact || variable.initial == Initial::approx)
      needs_start_because = "initial " + std::string{xml_name(variable.initial)};
    if (!needs_start_because.empty() && !variable.start)
      refuse(element, quoted + ": needs a start value (" + needs_start_because + ")");
    if (variable.initial == Initial::calculated && variable.start)
      refuse(element, quoted + ": may not have a start value (initial calculated)");
  }

  void read_variables(pugi::xml_node list, std::vector<Variable>& variables) {
    std::map<std::string, pugi::xml_node, std::less<>> names;
    std::map<std::pair<VariableType, std::uint32_t>, std::size_t> references;
    std::optional<std::size_t> independent;
    for (const pugi::xml_node element : list.children()) {
      if (element.type() != pugi::node_element) continue;
      Variable read = variable(element);
      const std::string quoted = "\"" + read.name + "\"";
      if (const auto [first, added] = names.emplace(read.name, element); !added)
        refuse(element, "variable name " + quoted + " is used twice (first on line " + line(first->second) + ")");
      // 3.0: one value reference, one variable. 2.0: per base type, and variables sharing one are aliases of
      // which at most one may give a start value.
      const VariableType space = version_ == FmiVersion::v3 ? VariableType::float64 : base_type(read.type);
      if (const auto [first, added] = references.emplace(std::pair{space, read.value_reference}, variables.size());
          !added) {
        const Variable& other = variables[first->second];
        const std::string where = "\"" + other.name + "\" (line " + line(elements_[first->second]) + ")";
        if (version_ == FmiVersion::v3)
          refuse(element, quoted + ": valueReference " + std::to_string(read.value_reference) + " is the one of " +
                              where + " already");
        if (read.start && other.start && read.variability != Variability::constant)
          refuse(element, quoted + ": an alias of " + where + " (same valueReference), and both have a start value");
      }
      if (read.causality == Causality::independent) {
        if (independent)
          refuse(element,
                 quoted + ": a second independent variable (the first is \"" + variables[*independent].name + "\")");
        independent = variables.size();
      }
      variables.push_back(std::move(read));
      elements_.push_back(element);
    }
    if (version_ == FmiVersion::v3 && !independent)
      refuse(list, "no independent variable (FMI 3.0 needs one, usually \"time\")");
  }

  std::vector<std::size_t> outputs(pugi::xml_node structure, const std::vector<Variable>& variables) const {
    std::vector<std::pair<pugi::xml_node, std::size_t>> listed;
    if (version_ == FmiVersion::v2) {
      if (const pugi::xml_node list = structure.child("Outputs")) {
        if (!list.first_child()) refuse(list, "<Outputs> lists nothing");
        for (const pugi::xml_node unknown : list.children("Unknown")) {
          const std::uint32_t index = required_number(unknown, "index");
          if (index < 1 || index > variables.size())
            refuse(unknown, "<Unknown index=\"" + std::to_string(index) + "\">: there is no variable " +
                                std::to_string(index) + " (<ModelVariables> has " + std::to_string(variables.size()) +
                                ")");
          listed.emplace_back(unknown, index - 1);
        }
      }
    } else {
      for (const pugi::xml_node output : structure.children("Output")) {
        const std::uint32_t reference = required_number(output, "valueReference");
        const auto found = std::find_if(variables.begin(), variables.end(),
                                        [&](const Variable& each) { return each.value_reference == reference; });
        if (found == variables.end())
          refuse(output,
                 "<Output valueReference=\"" + std::to_string(reference) + "\">: no variable has that value reference");
        listed.emplace_back(output, static_cast<std::size_t>(found - variables.begin()));
      }
    }
    std::vector<std::size_t> indices;
    for (const auto& [node, index] : listed) {
      if (variables[index].causality != Causality::output)
        refuse(node, "\"" + variables[index].name + "\" is listed as an output but its causality is " +
                         std::string{xml_name(variables[index].causality)});
      if (std::find(indices.begin(), indices.end(), index) != indices.end())
        refuse(node, "output \"" + variables[index].name + "\" is listed twice");
      indices.push_back(index);
    }
    for (std::size_t index = 0; index < variables.size(); ++index)
      if (variables[index].causality == Causality::output &&
          std::find(indices.begin(), indices.end(), index) == indices.end())
        refuse(elements_[index], "output \"" + variables[index].name + "\" is not listed in <ModelStructure>");
    return indices;
  }

  std::string_view xml_;
  FmiVersion version_ = FmiVersion::v3;
  std::vector<pugi::xml_node> elements_;  // each variable's element, for the lines of later problems
};

}  // namespace

Result<ModelDescription> read_model_description(std::string_view xml) {
  try {
    return DescriptionReader{xml}.read();
  } catch (const Problem& problem) {
    return Failure{problem.message};
  }
}

}  // namespace duet::fmi
