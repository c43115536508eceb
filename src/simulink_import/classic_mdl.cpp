#include "duet/simulink_import/classic_mdl.hpp"

#include <cctype>
#include <map>
#include <utility>

#include "mdl_encoding.hpp"
#include "mdl_syntax.hpp"
#include "mdl_system.hpp"

namespace duet::simulink_import {
namespace {

// The section of that name among the parent's children, null when there is none.
Result<const MdlNode*> only_section(const MdlNode& parent, std::string_view name, const std::string& file) {
  const MdlNode* found = nullptr;
  for (const MdlNode& child : parent.children) {
    if (!child.is_section || child.name != name) continue;
    if (found)
      return mdl_failure(
          file, child.line,
          "a second '" + std::string{name} + "' section (the first on line " + std::to_string(found->line) + ")");
    found = &child;
  }
  return found;
}

// The classic format stores only Simulink's version (`Version 10.0`), which no table maps to a release; newer files
// say it in words: `Description "Simulink model saved in R2025b"`.
std::string release_named(const std::string& description) {
  constexpr std::string_view marker = "saved in R";
  const std::size_t at = description.find(marker);
  if (at == std::string::npos) return {};
  const std::string release = description.substr(at + marker.size() - 1, 6);
  const bool well_formed =
      release.size() == 6 && std::isdigit(static_cast<unsigned char>(release[1])) &&
      std::isdigit(static_cast<unsigned char>(release[2])) && std::isdigit(static_cast<unsigned char>(release[3])) &&
      std::isdigit(static_cast<unsigned char>(release[4])) && (release[5] == 'a' || release[5] == 'b');
  return well_formed ? release : std::string{};
}

// `BlockParameterDefaults { Block { BlockType Gain  Gain "1" ... } ... }`: templates, never blocks of the model.
Status read_defaults(const MdlNode& section, SimulinkModel& model, const std::string& file) {
  for (const MdlNode& child : section.children) {
    if (!child.is_section || child.name != "Block") continue;
    const std::string type = pair_value(child, "BlockType");
    if (type.empty()) return mdl_failure(file, child.line, "default block without a BlockType");
    const auto [defaults, added] = model.defaults.try_emplace(type);
    if (!added) return mdl_failure(file, child.line, "defaults of BlockType '" + type + "' given twice");
    Status pairs = add_mdl_pairs(child, defaults->second, file, {"BlockType"});
    if (!pairs) return pairs;
  }
  return done();
}

// The `Simulink.ConfigSet` sections of the model's arrays by their `$ObjectID`.
void collect_config_sets(const MdlNode& array, std::map<std::string, const MdlNode*>& sets) {
  for (const MdlNode& child : array.children) {
    if (!child.is_section) continue;
    if (child.name == "Simulink.ConfigSet") sets.emplace(pair_value(child, "$ObjectID"), &child);
    if (child.name == "Array") collect_config_sets(child, sets);
  }
}

const MdlNode* solver_component(const MdlNode& section) {
  for (const MdlNode& child : section.children) {
    if (!child.is_section) continue;
    if (child.name == "Simulink.SolverCC") return &child;
    if (child.name != "Array") continue;
    if (const MdlNode* found = solver_component(child)) return found;
  }
  return nullptr;
}

// The active configuration set is named by `Object { $PropName "ActiveConfigurationSet" $ObjectID 9 }` and defined
// in an `Array`; a file with a single set and no such reference uses that one. The `$`-pairs are the file's object
// bookkeeping, not settings.
Status read_solver(const MdlNode& model_section, SimulinkModel& model, const std::string& file) {
  std::map<std::string, const MdlNode*> sets;
  const MdlNode* reference = nullptr;
  for (const MdlNode& child : model_section.children) {
    if (!child.is_section) continue;
    if (child.name == "Array") collect_config_sets(child, sets);
    if (pair_value(child, "$PropName") == "ActiveConfigurationSet") reference = &child;
  }
  const MdlNode* active = nullptr;
  if (reference && solver_component(*reference)) {
    active = reference;  // defined where it is named
  } else if (reference) {
    const std::string id = pair_value(*reference, "$ObjectID");
    const auto set = sets.find(id);
    if (set == sets.end())
      return mdl_failure(file, reference->line,
                         "ActiveConfigurationSet names $ObjectID '" + id + "', which no Simulink.ConfigSet has");
    active = set->second;
  } else if (sets.size() == 1) {
    active = sets.begin()->second;
  }
  const MdlNode* solver = active ? solver_component(*active) : nullptr;
  if (!solver) return done();
  for (const MdlNode& child : solver->children) {
    if (child.is_section || child.name.empty() || child.name.starts_with('$')) continue;
    if (!model.solver.parameters.emplace(child.name, child.value).second)
      return mdl_failure(file, child.line, "'" + child.name + "' given twice in Simulink.SolverCC");
  }
  return done();
}

Result<SimulinkModel> read_model(const MdlNode& section, const std::string& file) {
  SimulinkModel model;
  model.format = "mdl (classic)";
  model.name = pair_value(section, "Name");
  if (model.name.empty()) return mdl_failure(file, section.line, "the model has no Name");
  model.release = release_named(pair_value(section, "Description"));
  const Result<const MdlNode*> defaults = only_section(section, "BlockParameterDefaults", file);
  if (!defaults) return Failure{defaults.error()};
  const Result<const MdlNode*> root = only_section(section, "System", file);
  if (!root) return Failure{root.error()};
  if (!root.value()) return mdl_failure(file, section.line, "the model has no System");
  if (defaults.value()) {
    Status read = read_defaults(*defaults.value(), model, file);
    if (!read) return Failure{read.error()};
  }
  Status solver = read_solver(section, model, file);
  if (!solver) return Failure{solver.error()};
  Result<System> system = read_mdl_system(*root.value(), model.name, file);
  if (!system) return Failure{system.error()};
  model.root = std::move(system).value();
  return model;
}

}  // namespace

Result<SimulinkModel> read_classic_mdl(std::string_view bytes, const std::string& file) {
  Result<std::string> text = mdl_text_as_utf8(bytes, file);
  if (!text) return Failure{text.error()};
  Result<MdlNode> top = parse_mdl_syntax(text.value(), file);
  if (!top) return Failure{top.error()};
  // Stateflow, MatData and whatever else follows the model are not the model's block diagram.
  for (const MdlNode& section : top.value().children)
    if (section.is_section && section.name == "Library")
      return mdl_failure(file, section.line, "a block library, not a model: import a model that uses it instead");
  const Result<const MdlNode*> model = only_section(top.value(), "Model", file);
  if (!model) return Failure{model.error()};
  if (!model.value()) return mdl_failure(file, 1, "no 'Model { ... }' section: not a classic Simulink model file");
  return read_model(*model.value(), file);
}

}  // namespace duet::simulink_import
