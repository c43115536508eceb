#include "duet/model/validate.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "duet/model/block_types.hpp"
#include "duet/model/rates.hpp"
#include "duet/support/closest_word.hpp"

namespace duet::model {
namespace {

std::string list_of(const std::vector<std::string_view>& names) {
  std::string text;
  for (std::string_view name : names) text += (text.empty() ? "" : ", ") + std::string{name};
  return text.empty() ? "none" : text;
}

// A type's inputs, the optional ones last.
std::vector<std::string_view> all_inputs(const BlockType& type) {
  std::vector<std::string_view> names = type.inputs;
  names.insert(names.end(), type.optional_inputs.begin(), type.optional_inputs.end());
  return names;
}

// "u1", "u2", ...: the ports of a block with any number of inputs.
bool is_numbered_input(const std::string& port) {
  return port.size() >= 2 && port[0] == 'u' && port[1] != '0' &&
         std::all_of(port.begin() + 1, port.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string hint_for(std::string_view word, const std::vector<std::string>& candidates, const std::string& fallback) {
  std::vector<std::string_view> views(candidates.begin(), candidates.end());
  if (const auto closest = closest_word(word, views)) return "did you mean '" + std::string{*closest} + "'?";
  return fallback;
}

class Validator {
 public:
  explicit Validator(const Model& model) : model_(model) {
    for (const Parameter& parameter : model.parameters) names_.push_back(parameter.name);
    for (const Constant& constant : model.constants) names_.push_back(constant.name);
  }

  std::vector<Diagnostic> run() {
    check_scope(model_.blocks, {}, {}, "");
    unused_warnings();
    return std::move(diagnostics_);
  }

 private:
  struct Driver {
    std::string what;  // "block 'a' (output y)"
    Location location;
    std::string block;  // empty for a subsystem's input
  };
  struct Reader {
    std::string block;
    std::string port;
    std::string signal;
    Location location;
  };

  void error(Location location, std::string message, std::string hint = {}) {
    diagnostics_.push_back({Diagnostic::Severity::error, location, std::move(message), std::move(hint)});
  }
  void warning(Location location, std::string message, std::string hint = {}) {
    diagnostics_.push_back({Diagnostic::Severity::warning, location, std::move(message), std::move(hint)});
  }

  // Checks the blocks of one scope; `inputs` are the signals its subsystem brings in, `outputs` those it must drive;
  // `prefix` is its path ("imu/"), with which its signals are declared. Returns whether some output depends on some
  // input within a step (the subsystem's direct feedthrough).
  bool check_scope(const std::vector<Block>& blocks, const std::vector<Connection>& inputs,
                   const std::vector<Connection>& outputs, const std::string& prefix) {
    std::map<std::string, Driver> drivers;
    std::vector<Reader> readers;
    std::map<std::string, bool> feedthrough;  // by block name
    std::set<std::string> block_names;
    for (const Connection& input : inputs) {
      drivers[input.port] = {"the subsystem's input '" + input.port + "'", input.location, {}};
    }
    for (const Block& block : blocks) {
      if (!block_names.insert(block.name).second) {
        error(block.location, "two blocks are named '" + block.name + "'", "names are unique within a subsystem");
      }
      const BlockType* type = find_block_type(block.type);
      if (type == nullptr) {
        std::vector<std::string> known;
        for (const BlockType& t : block_types()) known.emplace_back(t.name);
        error(block.type_location, "unknown block type '" + block.type + "'",
              hint_for(block.type, known, "docs/MODELS.md lists the block types"));
        continue;
      }
      feedthrough[block.name] = block.code ? block.code->direct_feedthrough : type->direct_feedthrough;
      if (block.code) check_code_file(block);
      if (!type->user_defined_ports) check_ports_and_parameters(block, *type);
      if (block.type == "Subsystem") {
        const bool inner = check_scope(block.blocks, block.inputs, block.outputs, prefix + block.name + "/");
        feedthrough[block.name] = inner && block.trigger.kind == Trigger::Kind::none;
      }
      for (const auto& [name, parameter] : block.parameters) {
        if (parameter.reference.empty()) continue;
        used_.insert(parameter.reference);
        if (std::find(names_.begin(), names_.end(), parameter.reference) == names_.end() && !is_word_parameter(name)) {
          error(parameter.location,
                "parameter '" + name + "' of block '" + block.name + "' names '" + parameter.reference +
                    "', which is neither a parameter nor a constant of the model",
                hint_for(parameter.reference, names_, "define it under parameters or constants"));
        }
      }
      // An enabled or edge-triggered subsystem reads its enabling or triggering signal from here.
      if (!block.enable.empty()) readers.push_back({block.name, "enable", block.enable, block.location});
      if (block.trigger.kind == Trigger::Kind::edge) {
        readers.push_back({block.name, "trigger", block.trigger.signal, block.trigger.location});
      }
      // A subsystem's outward connections: its inputs read the parent's signals, its outputs drive them.
      for (const Connection& input : block.inputs)
        readers.push_back({block.name, input.port, input.signal, input.location});
      for (const Connection& output : block.outputs) {
        const Driver driver{"block '" + block.name + "' (output " + output.port + ")", output.location, block.name};
        const auto [found, added] = drivers.emplace(output.signal, driver);
        if (!added) {
          error(output.location,
                "signal '" + output.signal + "' has two drivers: " + found->second.what + " and " + driver.what,
                "a signal has exactly one driver");
        }
        driven_.insert(prefix + output.signal);
      }
    }
    std::vector<std::string> driven_here;
    for (const auto& [signal, driver] : drivers) driven_here.push_back(signal);
    for (const Reader& reader : readers) {
      if (drivers.count(reader.signal) != 0) continue;
      error(reader.location,
            "input '" + reader.port + "' of block '" + reader.block + "' reads signal '" + reader.signal +
                "', which nothing drives",
            hint_for(reader.signal, driven_here, "an output of a block, or of the subsystem's inputs, must drive it"));
    }
    for (const Connection& output : outputs) {
      if (drivers.count(output.port) == 0) {
        error(output.location, "output '" + output.port + "' of the subsystem is not driven inside it",
              "a block inside must drive a signal named '" + output.port + "'");
      }
    }
    if (block_names.size() == blocks.size())
      find_algebraic_loops(blocks, drivers, readers, feedthrough);  // names clear
    // Whether any of the subsystem's outputs depends on its inputs within a step.
    return depends_on_inputs(blocks, drivers, readers, feedthrough, inputs, outputs);
  }

  // The header of a Code block must be beside the model, where generation and simulation will include it from.
  void check_code_file(const Block& block) {
    const std::filesystem::path directory = std::filesystem::path{model_.file}.parent_path();
    const std::filesystem::path header = directory / block.code->file;
    if (!std::filesystem::is_regular_file(header)) {
      error(block.code->file_location,
            "file '" + block.code->file + "' of Code block '" + block.name + "' is not there",
            "the path is relative to the model file's folder" +
                std::string{directory.empty() ? std::string{} : " (" + directory.string() + ")"});
    }
  }

  void check_ports_and_parameters(const Block& block, const BlockType& type) {
    std::set<std::string> connected;
    for (const Connection& input : block.inputs) {
      const bool optional =
          std::find(type.optional_inputs.begin(), type.optional_inputs.end(), input.port) != type.optional_inputs.end();
      const bool known = optional || (type.variadic_inputs ? is_numbered_input(input.port)
                                                           : std::find(type.inputs.begin(), type.inputs.end(),
                                                                       input.port) != type.inputs.end());
      if (!known) {
        error(input.location, "block '" + block.name + "' (" + block.type + ") has no input '" + input.port + "'",
              type.variadic_inputs ? "its inputs are u1, u2, ..." : "its inputs: " + list_of(all_inputs(type)));
      }
      connected.insert(input.port);
    }
    if (type.variadic_inputs) {
      const auto numbered = static_cast<std::size_t>(std::count_if(
          block.inputs.begin(), block.inputs.end(), [](const Connection& c) { return is_numbered_input(c.port); }));
      // Arithmetic needs two operands; a message may be one value.
      const std::size_t fewest = block.type == "IpcSend" || block.type == "BytePack" ? 1 : 2;
      for (std::size_t k = 1; k <= std::max(fewest, numbered); ++k) {
        if (connected.count("u" + std::to_string(k)) == 0) {
          error(
              block.location, "input 'u" + std::to_string(k) + "' of block '" + block.name + "' is not connected",
              "a " + block.type + " takes inputs u1, u2, ... without gaps, at least " + (fewest == 1 ? "one" : "two"));
          break;
        }
      }
    } else {
      for (std::string_view port : type.inputs) {
        if (connected.count(std::string{port}) == 0) {
          error(block.location, "input '" + std::string{port} + "' of block '" + block.name + "' is not connected",
                "connect it: inputs: {" + std::string{port} + ": SIGNAL}");
        }
      }
    }
    for (const Connection& output : block.outputs) {
      if (std::find(type.outputs.begin(), type.outputs.end(), output.port) == type.outputs.end()) {
        error(output.location, "block '" + block.name + "' (" + block.type + ") has no output '" + output.port + "'",
              "its outputs: " + list_of(type.outputs));
      }
    }
    std::vector<std::string_view> names;
    for (const ParameterSpec& spec : type.parameters) names.push_back(spec.name);
    for (const auto& [name, parameter] : block.parameters) {
      if (std::find(names.begin(), names.end(), name) == names.end()) {
        error(parameter.location, "block '" + block.name + "' (" + block.type + ") has no parameter '" + name + "'",
              "its parameters: " + list_of(names));
      }
    }
    for (const ParameterSpec& spec : type.parameters) {
      const bool given = std::any_of(block.parameters.begin(), block.parameters.end(),
                                     [&spec](const auto& entry) { return entry.first == spec.name; });
      if (spec.required && !given) {
        error(block.location,
              "block '" + block.name + "' (" + block.type + ") needs parameter '" + std::string{spec.name} + "'",
              "parameters: {" + std::string{spec.name} + ": VALUE}");
      }
    }
  }

  // Blocks that feed each other within one step, around a cycle, cannot be computed: name them.
  void find_algebraic_loops(const std::vector<Block>& blocks, const std::map<std::string, Driver>& drivers,
                            const std::vector<Reader>& readers, const std::map<std::string, bool>& feedthrough) {
    // Edges: driver block -> reading block, where the reader passes its input straight on.
    std::map<std::string, std::vector<std::string>> next;
    for (const Reader& reader : readers) {
      const auto driver = drivers.find(reader.signal);
      const auto passes = feedthrough.find(reader.block);
      if (driver == drivers.end() || driver->second.block.empty() || passes == feedthrough.end() || !passes->second) {
        continue;
      }
      next[driver->second.block].push_back(reader.block);
    }
    std::map<std::string, int> state;  // 0 unvisited, 1 on the path, 2 done
    std::vector<std::string> path;
    std::map<std::string, Location> where;
    for (const Block& block : blocks) where[block.name] = block.location;
    bool reported = false;
    const auto visit = [&](const auto& self, const std::string& block) -> void {
      state[block] = 1;
      path.push_back(block);
      for (const std::string& following : next[block]) {
        if (reported) break;
        if (state[following] == 1) {
          const auto start = std::find(path.begin(), path.end(), following);
          std::string cycle;
          for (auto it = start; it != path.end(); ++it) cycle += "'" + *it + "' -> ";
          error(where[following], "algebraic loop: " + cycle + "'" + following + "'",
                "a block without direct feedthrough in the loop, such as a UnitDelay, breaks it");
          reported = true;
        } else if (state[following] == 0) {
          self(self, following);
        }
      }
      path.pop_back();
      state[block] = 2;
    };
    for (const Block& block : blocks) {
      if (!reported && state[block.name] == 0) visit(visit, block.name);
    }
  }

  // Whether a subsystem output is reached from a subsystem input through blocks with direct feedthrough only.
  static bool depends_on_inputs(const std::vector<Block>& blocks, const std::map<std::string, Driver>& drivers,
                                const std::vector<Reader>& readers, const std::map<std::string, bool>& feedthrough,
                                const std::vector<Connection>& inputs, const std::vector<Connection>& outputs) {
    std::set<std::string> reached;  // signals that depend on an input within the step
    for (const Connection& input : inputs) reached.insert(input.port);
    for (std::size_t round = 0; round <= blocks.size(); ++round) {
      for (const Reader& reader : readers) {
        if (reached.count(reader.signal) == 0) continue;
        const auto passes = feedthrough.find(reader.block);
        if (passes == feedthrough.end() || !passes->second) continue;
        for (const Block& block : blocks) {
          if (block.name != reader.block) continue;
          for (const Connection& output : block.outputs) reached.insert(output.signal);
        }
      }
    }
    (void)drivers;
    return std::any_of(outputs.begin(), outputs.end(),
                       [&reached](const Connection& output) { return reached.count(output.port) != 0; });
  }

  void unused_warnings() {
    for (const Parameter& parameter : model_.parameters) {
      if (used_.count(parameter.name) == 0) {
        warning(parameter.location, "parameter '" + parameter.name + "' is not used",
                "remove it, or use it in a block");
      }
    }
    for (const Constant& constant : model_.constants) {
      if (used_.count(constant.name) == 0) {
        warning(constant.location, "constant '" + constant.name + "' is not used", "remove it, or use it in a block");
      }
    }
    for (const SignalDeclaration& signal : model_.signals) {
      if (driven_.count(signal.name) == 0) {
        warning(signal.location, "signal '" + signal.name + "' is declared but nothing drives it",
                "remove the declaration, or drive the signal");
      }
    }
  }

  const Model& model_;
  std::vector<std::string> names_;  // of parameters and constants
  std::set<std::string> used_;
  std::set<std::string> driven_;
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace

std::vector<Diagnostic> validate(const Model& model) {
  std::vector<Diagnostic> diagnostics = Validator{model}.run();
  if (!has_errors(diagnostics)) {  // rates are only meaningful between blocks that are all there and connected
    const RateAnalysis rates = analyse_rates(model);
    diagnostics.insert(diagnostics.end(), rates.diagnostics.begin(), rates.diagnostics.end());
  }
  return diagnostics;
}

}  // namespace duet::model
