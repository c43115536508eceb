#include "duet/fmu_plant/fmu_mapping.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <span>

#include "duet/support/closest_word.hpp"
#include "duet/support/text_file.hpp"

namespace duet::fmu_plant {
namespace {

using Problem = std::optional<Failure>;

std::optional<double> number_or_truth(const std::string& text) {
  if (text == "true") return 1.0;
  if (text == "false") return 0.0;
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (used != text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

class MappingReader {
 public:
  explicit MappingReader(std::string file) : file_(std::move(file)) {}

  [[nodiscard]] std::string place(const YAML::Node& node) const {
    return file_ + ":" + std::to_string(node.Mark().line + 1);
  }
  [[nodiscard]] Failure at(const YAML::Node& node, const std::string& what) const {
    return Failure{place(node) + ": " + what};
  }

  [[nodiscard]] Problem only(const YAML::Node& map, std::span<const std::string_view> known) const {
    for (const auto& entry : map) {
      const std::string key = entry.first.Scalar();
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      std::string what = "unknown key '" + key + "'";
      if (const auto closest = closest_word(key, known)) {
        what.append(" (did you mean '").append(*closest).append("'?)");
      } else {
        what += " (known:";
        for (const std::string_view word : known) what.append(" ").append(word);
        what += ")";
      }
      return at(entry.first, what);
    }
    return std::nullopt;
  }

  // One list of connections: `- {variable: y, resource: "adc:ADC1/6", element: 0, unit: V}`.
  [[nodiscard]] Problem connections(const YAML::Node& list, std::vector<Connection>& out) const {
    if (!list.IsSequence()) return at(list, "expected a list of {variable, resource, element, unit}");
    for (const YAML::Node& item : list) {
      if (!item.IsMap()) return at(item, "expected {variable: NAME, resource: \"kind:NAME\"}");
      constexpr std::array<std::string_view, 4> keys = {"variable", "resource", "element", "unit"};
      if (auto problem = only(item, keys)) return problem;
      Connection connection{.line = item.Mark().line + 1};
      for (const char* key : {"variable", "resource"}) {
        if (!item[key] || !item[key].IsScalar() || item[key].Scalar().empty())
          return at(item, std::string{"needs "} + key);
      }
      connection.variable = item["variable"].Scalar();
      connection.resource = item["resource"].Scalar();
      if (connection.resource.find(':') == std::string::npos)
        return at(item["resource"], "resource \"" + connection.resource + "\" is not kind:NAME (e.g. \"adc:ADC1/6\")");
      if (const YAML::Node element = item["element"]) {
        const std::optional<double> index = element.IsScalar() ? number_or_truth(element.Scalar()) : std::nullopt;
        if (!index || *index < 0 || *index != std::trunc(*index) || *index > 65535)
          return at(element, "element: expected an index 0..65535");
        connection.element = static_cast<std::size_t>(*index);
      }
      if (const YAML::Node unit = item["unit"]) connection.unit = unit.Scalar();
      out.push_back(std::move(connection));
    }
    return std::nullopt;
  }

  [[nodiscard]] Result<FmuMapping> read(const YAML::Node& root) const {
    FmuMapping mapping{.file = file_};
    if (root.IsNull()) return mapping;  // an FMU without inputs may need nothing said
    if (!root.IsMap()) return at(root, "expected a map with inputs, outputs, set, observe");
    constexpr std::array<std::string_view, 4> keys = {"inputs", "outputs", "set", "observe"};
    if (auto problem = only(root, keys)) return *problem;
    if (root["inputs"]) {
      if (auto problem = connections(root["inputs"], mapping.inputs)) return *problem;
    }
    if (root["outputs"]) {
      if (auto problem = connections(root["outputs"], mapping.outputs)) return *problem;
    }
    if (const YAML::Node set = root["set"]) {
      if (!set.IsMap()) return at(set, "set: expected a map of NAME: VALUE");
      for (const auto& entry : set) {
        const std::optional<double> value =
            entry.second.IsScalar() ? number_or_truth(entry.second.Scalar()) : std::nullopt;
        if (!value) return at(entry.second, entry.first.Scalar() + ": expected a number, true or false");
        mapping.settings.push_back({entry.first.Scalar(), *value, place(entry.first)});
      }
    }
    if (const YAML::Node observe = root["observe"]) {
      if (!observe.IsSequence()) return at(observe, "observe: expected a list of variable names");
      for (const YAML::Node& name : observe) mapping.observed.push_back(name.Scalar());
    }
    return mapping;
  }

 private:
  std::string file_;
};

const fmi::Variable* find(const fmi::ModelDescription& description, const std::string& name) {
  const auto found = std::find_if(description.variables.begin(), description.variables.end(),
                                  [&name](const fmi::Variable& variable) { return variable.name == name; });
  return found == description.variables.end() ? nullptr : &*found;
}

// "the FMU has no variable 'x' (did you mean 'y'?)"
std::string unknown(const fmi::ModelDescription& description, const std::string& name) {
  std::vector<std::string_view> names;
  for (const fmi::Variable& variable : description.variables) names.emplace_back(variable.name);
  std::string what = "the FMU has no variable '" + name + "'";
  if (const auto closest = closest_word(name, names)) what.append(" (did you mean '").append(*closest).append("'?)");
  return what;
}

bool numeric(const fmi::Variable& variable) {
  return variable.type != fmi::VariableType::string && variable.type != fmi::VariableType::binary &&
         variable.type != fmi::VariableType::clock;
}

Status check_connections(const FmuMapping& mapping, const fmi::ModelDescription& description,
                         const std::vector<Connection>& connections, fmi::Causality causality) {
  const bool inputs = causality == fmi::Causality::input;
  std::map<std::string, int> variables;                      // each FMU input driven once
  std::map<std::pair<std::string, std::size_t>, int> reads;  // each resource element answered once
  for (const Connection& connection : connections) {
    const std::string where = mapping.file + ":" + std::to_string(connection.line) + ": ";
    const fmi::Variable* variable = find(description, connection.variable);
    if (variable == nullptr) return Failure{where + unknown(description, connection.variable)};
    if (variable->causality != causality) {
      return Failure{where + "'" + variable->name + "' is " + std::string{fmi::xml_name(variable->causality)} +
                     ", not an " + (inputs ? "input" : "output") + " of the FMU: under " +
                     (inputs ? "inputs" : "outputs") + " only the FMU's " + (inputs ? "inputs" : "outputs") +
                     " meet resources"};
    }
    if (!numeric(*variable))
      return Failure{where + "'" + variable->name + "' is a " + std::string{fmi::xml_name(variable->type)} +
                     ": only numbers meet resources"};
    if (!connection.unit.empty() && !variable->unit.empty() && connection.unit != variable->unit) {
      return Failure{where + "unit '" + connection.unit + "' differs from the FMU's '" + variable->unit + "' for '" +
                     variable->name + "'"};
    }
    if (inputs) {
      if (const auto [first, fresh] = variables.emplace(variable->name, connection.line); !fresh)
        return Failure{where + "'" + variable->name + "' is connected on line " + std::to_string(first->second) +
                       " already"};
    } else if (const auto [first, fresh] =
                   reads.emplace(std::pair{connection.resource, connection.element}, connection.line);
               !fresh) {
      return Failure{where + connection.resource + " element " + std::to_string(connection.element) +
                     " is answered on line " + std::to_string(first->second) + " already"};
    }
  }
  return done();
}

}  // namespace

Result<FmuMapping> read_fmu_mapping(const std::string& file) {
  auto text = read_text_file(file);
  if (!text) return Failure{text.error()};
  const MappingReader reader{file};
  try {
    return reader.read(YAML::Load(text.value()));
  } catch (const YAML::Exception& error) {
    return Failure{file + ":" + std::to_string(error.mark.line + 1) + ": " + error.msg};
  }
}

Status add_setting(FmuMapping& mapping, const std::string& text) {
  const std::size_t equals = text.find('=');
  const std::string place = "--fmu-set '" + text + "'";
  if (equals == std::string::npos || equals == 0) return Failure{place + ": write NAME=VALUE"};
  const std::optional<double> value = number_or_truth(text.substr(equals + 1));
  if (!value) return Failure{place + ": '" + text.substr(equals + 1) + "' is not a number, true or false"};
  mapping.settings.push_back({text.substr(0, equals), *value, place});
  return done();
}

Status check_fmu_mapping(const FmuMapping& mapping, const fmi::ModelDescription& description) {
  if (auto checked = check_connections(mapping, description, mapping.inputs, fmi::Causality::input); !checked)
    return checked;
  if (auto checked = check_connections(mapping, description, mapping.outputs, fmi::Causality::output); !checked)
    return checked;
  std::set<std::string> given;
  for (const Setting& setting : mapping.settings) {
    const fmi::Variable* variable = find(description, setting.variable);
    if (variable == nullptr) return Failure{setting.place + ": " + unknown(description, setting.variable)};
    const bool settable =
        variable->variability != fmi::Variability::constant &&
        (variable->causality == fmi::Causality::parameter || variable->causality == fmi::Causality::input ||
         variable->initial == fmi::Initial::exact || variable->initial == fmi::Initial::approx);
    if (!settable) {
      return Failure{setting.place + ": '" + variable->name + "' (" + std::string{fmi::xml_name(variable->causality)} +
                     ", " + std::string{fmi::xml_name(variable->variability)} + ") takes no value from outside"};
    }
    if (!numeric(*variable))
      return Failure{setting.place + ": '" + variable->name + "' is a " + std::string{fmi::xml_name(variable->type)} +
                     ": duet sets numbers only"};
    given.insert(variable->name);
  }
  for (const fmi::Variable& variable : description.variables) {
    if (variable.causality != fmi::Causality::input || given.contains(variable.name)) continue;
    const bool connected =
        std::any_of(mapping.inputs.begin(), mapping.inputs.end(),
                    [&variable](const Connection& input) { return input.variable == variable.name; });
    if (!connected) {
      return Failure{mapping.file + ": the FMU's input '" + variable.name +
                     "' is connected to no resource (under inputs) and given no value (under set)"};
    }
  }
  for (const std::string& name : mapping.observed) {
    const fmi::Variable* variable = find(description, name);
    if (variable == nullptr) return Failure{mapping.file + ": observe: " + unknown(description, name)};
    if (!numeric(*variable))
      return Failure{mapping.file + ": observe: '" + name + "' is a " + std::string{fmi::xml_name(variable->type)} +
                     ": only numbers are recorded"};
  }
  return done();
}

}  // namespace duet::fmu_plant
