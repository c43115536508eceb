#include "model_reference.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string_view>

#include "duet/model/data_type.hpp"
#include "duet/model/diagnostic.hpp"
#include "duet/support/closest_word.hpp"
#include "duet/support/number_text.hpp"

namespace duet::model {
namespace {

// The first problem found; caught once, in expand_references().
struct Problem {
  Diagnostic diagnostic;
};

[[noreturn]] void fail(const Location& location, const std::string& message, const std::string& hint = {}) {
  throw Problem{{Diagnostic::Severity::error, location, message, hint}};
}

std::string place(const Location& location, const std::string& own_file) {
  return (location.file.empty() ? own_file : location.file) + ":" + std::to_string(location.line) + ":" +
         std::to_string(location.column);
}

// Every place in a referenced model names its file, so that what validation says about it later points there.
void name_file(Location& location, const std::string& file) {
  if (location.file.empty()) location.file = file;
}

void name_file(Block& block, const std::string& file) {
  for (Location* location : {&block.location, &block.type_location, &block.period.location, &block.trigger.location,
                             &block.model_location}) {
    name_file(*location, file);
  }
  for (auto& [name, parameter] : block.parameters) name_file(parameter.location, file);
  for (Connection& connection : block.inputs) name_file(connection.location, file);
  for (Connection& connection : block.outputs) name_file(connection.location, file);
  if (block.code) {
    name_file(block.code->file_location, file);
    for (StateVariable& variable : block.code->state) name_file(variable.location, file);
  }
  for (Block& inner : block.blocks) name_file(inner, file);
}

void name_file(Model& model, const std::string& file) {
  name_file(model.base_period_location, file);
  name_file(model.xcp.location, file);
  for (Constant& constant : model.constants) name_file(constant.location, file);
  for (Parameter& parameter : model.parameters) name_file(parameter.location, file);
  for (SignalDeclaration& signal : model.signals) name_file(signal.location, file);
  for (Block& block : model.blocks) name_file(block, file);
}

// A Code block's header is named relative to its model's folder; from the referencing model's, through `folder`.
void move_code_files(Block& block, const std::filesystem::path& folder) {
  if (block.code) block.code->file = (folder / block.code->file).lexically_normal().generic_string();
  for (Block& inner : block.blocks) move_code_files(inner, folder);
}

bool same(const Value& a, const Value& b) { return a.elements == b.elements && a.shape == b.shape; }

bool same(const Parameter& a, const Parameter& b) {
  return same(a.value, b.value) && a.type == b.type && a.unit == b.unit && a.minimum == b.minimum &&
         a.maximum == b.maximum && a.description == b.description && a.labels == b.labels;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
  return text;
}

// A referenced model's Inport or Outport blocks, by name.
std::map<std::string, const Block*> ports_of(const Model& model, const std::string& type) {
  std::map<std::string, const Block*> ports;
  for (const Block& block : model.blocks) {
    if (block.type == type) ports[block.name] = &block;
  }
  return ports;
}

// The signal the port's block reads or drives (an Inport's y, an Outport's u), if connected.
std::optional<std::string> port_signal(const Block& port) {
  const std::vector<Connection>& connections = port.type == "Inport" ? port.outputs : port.inputs;
  if (connections.empty()) return std::nullopt;
  return connections.front().signal;
}

class Expander {
 public:
  Expander(Model& model, const std::vector<std::string>& chain) : model_(model), chain_(chain) {
    chain_.push_back(model.file);
  }

  void expand(std::vector<Block>& blocks, const std::string& prefix) {
    for (Block& block : blocks) {
      if (!block.model.empty()) {
        reference(block, prefix + block.name);
      } else {
        expand(block.blocks, prefix + block.name + "/");
      }
    }
  }

 private:
  void reference(Block& block, const std::string& path) {
    const std::filesystem::path folder = std::filesystem::path{block.model}.parent_path();
    const std::filesystem::path own_folder = std::filesystem::path{model_.file}.parent_path();
    const std::string file = (own_folder / block.model).lexically_normal().generic_string();
    if (!std::filesystem::is_regular_file(file)) {
      fail(block.model_location,
           "the model '" + block.model + "' that block '" + block.name + "' references is not there",
           "the path is relative to the referencing model's folder" +
               (own_folder.empty() ? std::string{} : " (" + own_folder.generic_string() + ")"));
    }
    check_cycle(block, file);
    auto loaded = load_referenced_model(file, chain_);
    if (!loaded) fail(block.model_location, "the model '" + block.model + "' cannot be used: " + loaded.error());
    Model referenced = std::move(loaded).value();
    name_file(referenced, file);
    if (referenced.base_period_us != model_.base_period_us) {
      fail(block.model_location,
           "the model '" + block.model + "' has base_period_us " + shortest_text(referenced.base_period_us) +
               ", the referencing model " + shortest_text(model_.base_period_us),
           "a reference runs at the referencing model's rates: give both the same base period");
    }
    join_definitions(block, referenced);
    bind(block, referenced, path);
    for (Block& inner : block.blocks) move_code_files(inner, folder);
  }

  void check_cycle(const Block& block, const std::string& file) const {
    std::error_code ignored;
    const std::filesystem::path target = std::filesystem::weakly_canonical(file, ignored);
    const auto start = std::find_if(chain_.begin(), chain_.end(), [&](const std::string& link) {
      return std::filesystem::weakly_canonical(link, ignored) == target;
    });
    if (start == chain_.end()) return;
    std::string cycle;
    for (auto link = start; link != chain_.end(); ++link) cycle += *link + " -> ";
    fail(block.model_location, "model reference cycle: " + cycle + file,
         "a model cannot contain itself, directly or through others");
  }

  // Parameters and constants are the models' together, by name; a name both define means the same on both sides.
  void join_definitions(const Block& block, const Model& referenced) {
    const auto conflict = [&](const std::string& name, const Location& theirs, const Location& ours) {
      fail(
          block.model_location,
          "'" + name + "' is defined differently in " + place(theirs, model_.file) + " and " + place(ours, model_.file),
          "the models share parameters and constants by name: give both the same definition, or rename one");
    };
    for (const Parameter& parameter : referenced.parameters) {
      const auto own = std::find_if(model_.parameters.begin(), model_.parameters.end(),
                                    [&](const Parameter& p) { return p.name == parameter.name; });
      if (const Constant* constant = find_constant(parameter.name))
        conflict(parameter.name, parameter.location, constant->location);
      if (own == model_.parameters.end()) {
        model_.parameters.push_back(parameter);
      } else if (!same(*own, parameter)) {
        conflict(parameter.name, parameter.location, own->location);
      }
    }
    for (const Constant& constant : referenced.constants) {
      const auto own = std::find_if(model_.parameters.begin(), model_.parameters.end(),
                                    [&](const Parameter& p) { return p.name == constant.name; });
      if (own != model_.parameters.end()) conflict(constant.name, constant.location, own->location);
      const Constant* same_name = find_constant(constant.name);
      if (same_name == nullptr) {
        model_.constants.push_back(constant);
      } else if (!same(same_name->value, constant.value)) {
        conflict(constant.name, constant.location, same_name->location);
      }
    }
  }

  [[nodiscard]] const Constant* find_constant(const std::string& name) const {
    const auto found = std::find_if(model_.constants.begin(), model_.constants.end(),
                                    [&](const Constant& c) { return c.name == name; });
    return found == model_.constants.end() ? nullptr : &*found;
  }

  // The reference's inputs name Inports, its outputs Outports: each becomes a port of the subsystem under the name of
  // the signal inside, so that the flattening connects it like any subsystem's.
  void bind(Block& block, Model& referenced, const std::string& path) {
    const auto inports = ports_of(referenced, "Inport");
    const auto outports = ports_of(referenced, "Outport");
    std::set<std::string> port_signals;  // inside, the referencing model's signals: their declarations are its own
    std::vector<Connection> inputs;
    for (const Connection& binding : block.inputs) {
      const Block& inport = port_block(inports, binding, block, "Inport");
      if (const auto signal = port_signal(inport)) {
        inputs.push_back({*signal, binding.signal, binding.location, std::nullopt, {}});
        port_signals.insert(*signal);
      }
    }
    std::vector<std::string> unbound;
    for (const auto& [name, inport] : inports) {
      const bool bound = std::any_of(block.inputs.begin(), block.inputs.end(),
                                     [&name = name](const Connection& c) { return c.port == name; });
      if (!bound) unbound.push_back(name);
    }
    if (!unbound.empty()) {
      fail(block.model_location,
           "the model '" + block.model + "' has " + (unbound.size() == 1 ? "an Inport" : "Inports") + " that block '" +
               block.name + "' does not bind: " + quoted_list(unbound),
           "bind every Inport to a signal: inputs: {" + unbound.front() + ": SIGNAL}");
    }
    std::vector<Connection> outputs;
    for (const Connection& binding : block.outputs) {
      const Block& outport = port_block(outports, binding, block, "Outport");
      const auto signal = port_signal(outport);
      if (!signal) {
        fail(outport.location, "Outport '" + outport.name + "' reads no signal", "connect it: inputs: {u: SIGNAL}");
      }
      outputs.push_back({*signal, binding.signal, binding.location, std::nullopt, {}});
      port_signals.insert(*signal);
    }
    block.inputs = std::move(inputs);
    block.outputs = std::move(outputs);
    for (Block& inner : referenced.blocks) {
      if (inner.type != "Inport" && inner.type != "Outport") block.blocks.push_back(std::move(inner));
    }
    for (SignalDeclaration& signal : referenced.signals) {
      if (port_signals.count(signal.name) != 0) continue;
      signal.name = path + "/" + signal.name;
      model_.signals.push_back(std::move(signal));
    }
  }

  static const Block& port_block(const std::map<std::string, const Block*>& ports, const Connection& binding,
                                 const Block& block, const std::string& type) {
    const auto found = ports.find(binding.port);
    if (found != ports.end()) return *found->second;
    std::vector<std::string_view> names;
    for (const auto& [name, port] : ports) names.push_back(name);
    std::vector<std::string> listed(names.begin(), names.end());
    const auto closest = closest_word(binding.port, names);
    fail(binding.location, "the model '" + block.model + "' has no " + type + " '" + binding.port + "'",
         closest ? "did you mean '" + std::string{*closest} + "'?"
                 : "its " + type + "s: " + (listed.empty() ? std::string{"none"} : quoted_list(listed)));
  }

  Model& model_;
  std::vector<std::string> chain_;  // the referencing files, then this model's
};

}  // namespace

Status expand_references(Model& model, const std::vector<std::string>& chain) {
  try {
    Expander{model, chain}.expand(model.blocks, "");
  } catch (const Problem& problem) {
    return Failure{format(model.file, problem.diagnostic)};
  }
  return done();
}

}  // namespace duet::model
