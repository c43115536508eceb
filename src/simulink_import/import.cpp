#include "duet/simulink_import/import.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <tuple>

#include "import_context.hpp"

namespace duet::simulink_import {
namespace {

// A duet identifier from a Simulink name: letters, digits and '_' kept, anything else one '_'.
std::string identifier(std::string_view name) {
  std::string text;
  for (const char c : name) {
    const bool word = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (word) {
      text += c;
    } else if (!text.empty() && text.back() != '_') {
      text += '_';
    }
  }
  while (!text.empty() && text.back() == '_') text.pop_back();
  if (text.empty() || (text[0] >= '0' && text[0] <= '9')) text = "b_" + text;
  return text;
}

// Names unique within one duet subsystem: a second "gain" becomes "gain_2".
class Names {
 public:
  std::string unique(const std::string& stem) {
    std::string name = stem;
    for (int n = 2; !used_.insert(name).second; ++n) name = stem + "_" + std::to_string(n);
    return name;
  }

 private:
  std::set<std::string> used_;
};

// What drives a subsystem's trigger port: the signal, and the block whose output it is (none through a subsystem's
// port), in the root system or not.
struct Trigger {
  std::vector<std::string> signals;
  const Block* driver = nullptr;
  bool in_root = false;
};

// Whether `driver`'s output is never below zero: a boolean or an unsigned integer. For such a signal Simulink's
// triggering edges (a rise from below zero to zero or above, or from zero to above; falls likewise) are duet's
// (from zero or below to above zero; from above zero to zero or below).
bool never_negative(const Block& driver, bool in_root) {
  static const std::set<std::string, std::less<>> comparisons{"RelationalOperator", "Logic", "Compare To Constant",
                                                              "Compare To Zero"};
  static const std::set<std::string, std::less<>> unsigned_types{"boolean", "uint8", "uint16", "uint32"};
  if (comparisons.count(type_name(driver)) != 0) return true;
  const bool typed = driver.type == "DataTypeConversion" || (driver.type == "Inport" && in_root);
  const auto type = driver.parameters.find("OutDataTypeStr");
  return typed && type != driver.parameters.end() && unsigned_types.count(type->second) != 0;
}

bool is_variable_path(std::string_view text) {
  if (text.empty()) return false;
  bool at_start = true;
  for (const char c : text) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    const bool digit = c >= '0' && c <= '9';
    if (c == '.') {
      if (at_start) return false;
      at_start = true;
    } else if (letter || (digit && !at_start)) {
      at_start = false;
    } else {
      return false;
    }
  }
  return !at_start;
}

class Importer final : public ImportModel {
 public:
  Importer(const SimulinkModel& model, const ImportOptions& options) : model_(model), options_(options) {}

  ImportResult run() {
    duet_.name = identifier(model_.name);
    duet_.description = "Imported from the Simulink model " + model_.name +
                        (model_.release.empty() ? "" : " (" + model_.release + ")") + " by duet import simulink";
    if (!solver()) return finish();
    duet_.base_period_us = base_period_us_;
    duet_.blocks = import_system(model_.root, model_.name, options_.variables, true, {}, {});
    return finish();
  }

  std::optional<std::string> parameter_text(ImportContext& context, const std::string& parameter,
                                            const std::string& expression) override {
    const std::string text = trimmed(expression);
    auto evaluated = evaluate(text, context.workspace());
    if (!evaluated) {
      context.refuse(parameter + " '" + text + "': " + evaluated.error());
      return std::nullopt;
    }
    if (evaluated.value().is_struct) {
      context.refuse(parameter + " '" + text + "' is a struct, not a number");
      return std::nullopt;
    }
    // A variable of the --variables files, not shadowed by a mask's: a model parameter of its name, tunable.
    const std::string root = text.substr(0, text.find('.'));
    const auto variable = options_.variables.find(root);
    const auto seen = context.workspace().find(root);  // a mask's parameter of the same name shadows it
    const bool from_variables = is_variable_path(text) && variable != options_.variables.end() &&
                                seen != context.workspace().end() && seen->second == variable->second &&
                                evaluated.value().type == MatlabClass::double_class;
    if (!from_variables) return yaml_value(evaluated.value());
    std::string name = identifier(text);
    if (parameter_names_.insert(name).second) {
      duet_.parameters.push_back({.name = name,
                                  .value = yaml_value(evaluated.value()),
                                  .type = {},
                                  .source = "the Simulink variable " + text + ", first used by " + context.path()});
    }
    return name;
  }
  [[nodiscard]] long long base_period_us() const override { return base_period_us_; }
  [[nodiscard]] const SimulinkModel& source() const override { return model_; }

 private:
  ImportResult finish() {
    if (result_.problems.empty()) {
      result_.model_text = duet_model_text(duet_);
      collect_floating_only(duet_.blocks, "");
    }
    return std::move(result_);
  }

  void collect_floating_only(const std::vector<DuetBlock>& blocks, const std::string& prefix) {
    for (const DuetBlock& block : blocks) {
      if (!block.floating_only.empty())
        result_.floating_only.push_back(
            {.block = prefix + block.name, .source = block.source, .why = block.floating_only});
      collect_floating_only(block.blocks, prefix + block.name + "/");
    }
  }

  void problem(const std::string& text) { result_.problems.push_back(text); }

  // A fixed-step solver, and the base period: --base-period-us, or the solver's fixed step.
  bool solver() {
    const auto& settings = model_.solver.parameters;
    const auto setting = [&settings](const char* name) {
      const auto found = settings.find(name);
      return found == settings.end() ? std::string{} : found->second;
    };
    std::string name = setting("SolverName");
    if (name.empty()) name = setting("Solver");
    const bool fixed = name.empty() || name.starts_with("FixedStep") || name == "ode1" || name == "ode2" ||
                       name == "ode3" || name == "ode4" || name == "ode5" || name == "ode8" || name == "ode14x" ||
                       name == "ode1be";
    if (!fixed) {
      problem(model_.name + ": the solver " + name +
              " is variable-step; duet runs fixed-step discrete models (set a fixed-step solver in Simulink)");
      return false;
    }
    if (options_.base_period_us) {
      base_period_us_ = *options_.base_period_us;
      return true;
    }
    const std::string step = trimmed(setting("FixedStep"));
    if (step.empty() || step == "auto") {
      problem(model_.name + ": the fixed step is '" + (step.empty() ? "not in the file" : step) +
              "'; give the base period with --base-period-us");
      return false;
    }
    auto seconds = evaluate(step, options_.variables);
    if (!seconds || !seconds.value().is_scalar() || !(seconds.value().elements.front() > 0)) {
      problem(model_.name + ": the fixed step '" + step + "' " +
              (seconds ? std::string{"is not a positive number"} : "cannot be evaluated: " + seconds.error()) +
              "; give --variables or --base-period-us");
      return false;
    }
    const double microseconds = seconds.value().elements.front() * 1e6;
    base_period_us_ = std::llround(microseconds);
    if (base_period_us_ < 1 || std::fabs(microseconds - static_cast<double>(base_period_us_)) > 1e-6 * microseconds) {
      problem(model_.name + ": the fixed step " + step + " s is not a whole number of microseconds");
      return false;
    }
    return true;
  }

  // The signal each output port drives, by (block, port); and the source feeding each input port.
  struct Wiring {
    std::map<std::pair<std::string, int>, std::string> driven;  // (block, out port) -> signal
    std::map<std::tuple<std::string, std::string, int>, std::pair<std::string, int>> fed;  // (block, kind, port)
  };

  Wiring wire(const System& system, const std::string& path, Names& signals) {
    Wiring wiring;
    std::map<std::string, const Block*> blocks;
    for (const Block& block : system.blocks) blocks[block.name] = &block;
    for (const Line& line : system.lines) {
      if (!line.source) continue;
      const std::pair key{line.source->block, line.source->port};
      if (wiring.driven.count(key) == 0) {
        const Block& source = *blocks.at(line.source->block);
        std::string stem = identifier(line.name);
        if (line.name.empty()) {
          const auto named = source.output_names.find(line.source->port);
          stem = named != source.output_names.end()
                     ? identifier(named->second)
                     : identifier(source.name) +
                           (line.source->port > 1 ? "_" + std::to_string(line.source->port) : std::string{});
        }
        wiring.driven[key] = signals.unique(stem);
      }
      for (const Endpoint& destination : line.destinations) {
        const auto [at, fresh] = wiring.fed.emplace(std::tuple{destination.block, destination.kind, destination.port},
                                                    std::pair{line.source->block, line.source->port});
        if (!fresh && at->second != key) {
          problem(path + "/" + destination.block + ": its " + destination.kind + " port " +
                  std::to_string(destination.port) + " has two sources");
        }
      }
    }
    return wiring;
  }

  // The blocks of one system. A subsystem's Inport and Outport blocks become its inputs and outputs; at the root
  // they are the model's Inports and Outports: its interface.
  std::vector<DuetBlock> import_system(const System& system, const std::string& path, const Workspace& workspace,
                                       bool root, TextPairs* subsystem_inputs, TextPairs* subsystem_outputs) {
    Names signals;
    Names names;
    const Wiring wiring = wire(system, path, signals);
    // A From block reads what the Goto of its tag is fed with (local tags only).
    std::map<std::string, std::pair<std::string, int>> goto_sources;
    for (const Block& block : system.blocks) {
      if (block.type != "Goto") continue;
      const auto fed = wiring.fed.find({block.name, "in", 1});
      if (fed != wiring.fed.end()) goto_sources[stored_or(block, "GotoTag", "A")] = fed->second;
    }
    const auto named = [&system](const std::string& name) -> const Block* {
      const auto block = std::find_if(system.blocks.begin(), system.blocks.end(),
                                      [&](const Block& each) { return each.name == name; });
      return block == system.blocks.end() ? nullptr : &*block;
    };
    // The block output that drives `source`, through From blocks to what their Goto is fed with.
    const auto driver_of = [&](std::pair<std::string, int> source) -> std::optional<std::pair<std::string, int>> {
      for (int hops = 0; hops < 100; ++hops) {
        const Block* block = named(source.first);
        if (block == nullptr || block->type != "From") break;
        const auto found = goto_sources.find(stored_or(*block, "GotoTag", "A"));
        if (found == goto_sources.end()) return std::nullopt;
        source = found->second;
      }
      return source;
    };
    const auto signal_of = [&](std::pair<std::string, int> source) -> std::string {
      const auto driver = driver_of(source);
      const auto driven = driver ? wiring.driven.find(*driver) : wiring.driven.end();
      return driven == wiring.driven.end() ? std::string{} : driven->second;
    };
    const auto trigger_driver = [&](const Block& subsystem) -> const Block* {
      const auto fed = wiring.fed.find({subsystem.name, "trigger", 1});
      if (fed == wiring.fed.end()) return nullptr;
      const auto driver = driver_of(fed->second);
      return driver ? named(driver->first) : nullptr;
    };
    const auto input_signals = [&](const Block& block, const std::string& kind) {
      std::vector<std::string> inputs;
      for (const auto& [key, source] : wiring.fed) {
        if (std::get<0>(key) != block.name || std::get<1>(key) != kind) continue;
        const auto port = static_cast<std::size_t>(std::get<2>(key));
        if (inputs.size() < port) inputs.resize(port);
        inputs[port - 1] = signal_of(source);
      }
      return inputs;
    };
    const auto output_signals = [&](const Block& block) {
      std::vector<std::string> outputs;
      for (const auto& [key, signal] : wiring.driven) {
        if (key.first != block.name) continue;
        if (outputs.size() < static_cast<std::size_t>(key.second)) outputs.resize(static_cast<std::size_t>(key.second));
        outputs[static_cast<std::size_t>(key.second) - 1] = signal;
      }
      return outputs;
    };

    const std::set<std::string> callers = function_call_sources(system, path, wiring);
    std::vector<DuetBlock> blocks;
    for (const Block& block : system.blocks) {
      const std::string block_path = path + "/" + block.name;
      if (callers.count(block.name) != 0) {
        result_.report.push_back({.path = block_path,
                                  .type = block.type,
                                  .imported = true,
                                  .what = "raises function calls that --interrupt maps to interrupts: the interrupts "
                                          "stand in for it"});
        continue;
      }
      const std::vector<std::string> inputs = input_signals(block, "in");
      const std::vector<std::string> outputs = output_signals(block);
      Verdict verdict{.path = block_path, .type = block.type, .imported = false, .what = {}};
      if (block.parameters.count("Commented") != 0 && block.parameters.at("Commented") != "off") {
        verdict.what = "commented out (" + block.parameters.at("Commented") + "): refused, uncomment or delete it";
        refuse(verdict);
        continue;
      }
      if (block.type == "Inport" || block.type == "Outport") {
        port_block(block, block_path, root, inputs, outputs, subsystem_inputs, subsystem_outputs, blocks, names,
                   signals, verdict);
        continue;
      }
      if (block.type == "Goto" || block.type == "From") {
        const bool local =
            block.parameters.count("TagVisibility") == 0 || block.parameters.at("TagVisibility") == "local";
        verdict.imported = local;
        verdict.what =
            local ? "joined to its tag's signal" : "a scoped or global tag: refused, use lines or local tags";
        if (!local)
          refuse(verdict);
        else
          result_.report.push_back(verdict);
        continue;
      }
      if (block.type == "EnablePort" || block.type == "TriggerPort") {
        verdict.imported = true;
        verdict.what = "its subsystem's " + std::string{block.type == "EnablePort" ? "enable" : "trigger"};
        result_.report.push_back(verdict);
        continue;
      }
      if (block.type == "SubSystem") {
        subsystem(block, block_path, workspace, inputs, outputs, input_signals(block, "enable"),
                  {input_signals(block, "trigger"), trigger_driver(block), root}, blocks, names, signals, verdict);
        continue;
      }
      const std::string type = type_name(block);
      verdict.type = type;
      const BlockMapping mapping = mapping_for(type);
      if (mapping == nullptr) {
        verdict.what = why_not(block, type);
        refuse(verdict);
        continue;
      }
      ImportContext context{*this, block, block_path, workspace, inputs, outputs};
      context.block_name = names.unique(identifier(block.name));
      context.set_namers([&names](const std::string& stem) { return names.unique(stem); },
                         [&signals](const std::string& stem) { return signals.unique(stem); });
      mapping(context);
      if (context.refused()) {
        verdict.what = context.reason();
        refuse(verdict);
        continue;
      }
      verdict.imported = true;
      verdict.what = context.emitted().empty() ? "nothing to bring over" : context.what();
      result_.report.push_back(verdict);
      for (DuetBlock& made : context.emitted()) blocks.push_back(std::move(made));
    }
    return blocks;
  }

  // Whether `block` is a function-call subsystem that --interrupt maps to an interrupt.
  bool mapped_function_call(const Block& block, const std::string& block_path) const {
    if (block.type != "SubSystem" || block.systems.empty() || options_.interrupts.count(block_path) == 0) return false;
    return std::any_of(block.systems[0].blocks.begin(), block.systems[0].blocks.end(), [](const Block& inside) {
      const auto type = inside.parameters.find("TriggerType");
      return inside.type == "TriggerPort" && type != inside.parameters.end() && type->second == "function-call";
    });
  }

  // The blocks whose every output goes to the trigger of a function-call subsystem --interrupt maps, or to such
  // blocks (an interrupt block, and a Demux of its calls): in duet the interrupts raise those subsystems instead.
  std::set<std::string> function_call_sources(const System& system, const std::string& path, const Wiring& wiring) {
    std::set<std::string> callers;
    std::set<std::string> mapped;
    for (const Block& block : system.blocks)
      if (mapped_function_call(block, path + "/" + block.name)) mapped.insert(block.name);
    if (mapped.empty()) return callers;
    for (bool grew = true; grew;) {
      grew = false;
      for (const Block& block : system.blocks) {
        if (callers.count(block.name) != 0 || mapped.count(block.name) != 0) continue;
        bool drives = false;
        bool only_calls = true;
        for (const auto& [destination, source] : wiring.fed) {
          if (source.first != block.name) continue;
          drives = true;
          const auto& [name, kind, port] = destination;
          only_calls = only_calls && ((kind == "trigger" && mapped.count(name) != 0) || callers.count(name) != 0);
        }
        if (drives && only_calls) grew = callers.insert(block.name).second;
      }
    }
    return callers;
  }

  void refuse(Verdict verdict) {
    std::string path = verdict.path;
    std::replace(path.begin(), path.end(), '\n', ' ');  // a message is one line
    problem(path + " (" + verdict.type + "): " + verdict.what);
    result_.report.push_back(std::move(verdict));
  }

  static std::string why_not(const Block& block, const std::string& type) {
    if (block.type == "Reference") {
      const std::string source = block.parameters.count("SourceBlock") ? block.parameters.at("SourceBlock") : "";
      return "a link to the library block '" + source + "' (" + type +
             "), which duet has no implementation of (docs/IMPORT.md lists the ones it has)";
    }
    if (block.type == "S-Function") return "an S-Function: its code is not in the model";
    if (type == "Integrator" || type == "TransferFcn" || type == "StateSpace" || type == "Derivative" ||
        type == "ZeroPole" || type == "TransportDelay") {
      return "a continuous block: duet imports discrete models only (discretise it in Simulink)";
    }
    return "no duet block has the semantics of a " + type + " block (docs/IMPORT.md lists the ones it has)";
  }

  void port_block(const Block& block, const std::string& block_path, bool root, const std::vector<std::string>& inputs,
                  const std::vector<std::string>& outputs, TextPairs* subsystem_inputs, TextPairs* subsystem_outputs,
                  std::vector<DuetBlock>& blocks, Names& names, Names& signals, Verdict& verdict) {
    const bool inport = block.type == "Inport";
    const std::string port = stored_or(block, "Port", "1");
    const std::string name = identifier(block.name);
    if (inport && outputs.empty()) {
      verdict.imported = true;
      verdict.what = "unconnected";
      result_.report.push_back(verdict);
      return;
    }
    if (!inport && (inputs.empty() || inputs[0].empty())) {
      verdict.what = "its input is not connected";
      refuse(verdict);
      return;
    }
    if (!inport && !root) {
      if (stored_or(block, "OutputWhenDisabled", "held") != "held" || stored_or(block, "InitialOutput", "[]") != "[]") {
        verdict.what =
            "it resets or starts from an initial output while its subsystem is disabled; duet's "
            "subsystems hold their outputs";
        refuse(verdict);
        return;
      }
    }
    if (root) {
      // A plant hands doubles; an inport of another type converts them, as its OutDataTypeStr says.
      const auto declared = block.parameters.find("OutDataTypeStr");
      const bool typed = inport && declared != block.parameters.end() && declared->second != "double" &&
                         !declared->second.starts_with("Inherit:");
      if (typed && !is_duet_type(declared->second)) {
        verdict.what = "OutDataTypeStr '" + declared->second + "' is no type duet has";
        refuse(verdict);
        return;
      }
      const std::string read = typed ? signals.unique(name + "_read") : inport ? outputs[0] : std::string{};
      // The model's interface: on its own the plant's resources inport:NAME and outport:NAME, referenced by another
      // model (a Subsystem with model: FILE) bound to that model's signals.
      const std::string unique = names.unique(name);
      DuetBlock made{.name = unique, .type = inport ? "Inport" : "Outport"};
      if (inport)
        made.outputs = {{"y", read}};
      else
        made.inputs = {{"u", inputs[0]}};
      made.source = block_path + " (" + block.type + " " + port + ")";
      blocks.push_back(std::move(made));
      if (typed) {
        blocks.push_back({.name = names.unique(name + "_as_" + declared->second),
                          .type = "Convert",
                          .parameters = {{"type", declared->second}},
                          .inputs = {{"u", read}},
                          .outputs = {{"y", outputs[0]}},
                          .source = block_path + " (Inport " + port + "): its type, " + declared->second});
      }
      verdict.imported = true;
      verdict.what =
          std::string{inport ? "Inport (on its own the plant's inport:" : "Outport (on its own the plant's outport:"} +
          unique + ")";
      result_.report.push_back(verdict);
      return;
    }
    // Inside a subsystem: the port's place in the subsystem's inputs or outputs, by its number.
    TextPairs& ports = inport ? *subsystem_inputs : *subsystem_outputs;
    std::size_t index = 0;
    const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), index);
    if (error != std::errc{} || end != port.data() + port.size() || index < 1 || index > 1000) {
      verdict.what = "its Port '" + port + "' is not a port number from 1 to 1000";
      refuse(verdict);
      return;
    }
    if (ports.size() < index) ports.resize(index);
    ports[index - 1].first = inport ? outputs[0] : inputs[0];
    verdict.imported = true;
    verdict.what = std::string{inport ? "input " : "output "} + port + " of its subsystem";
    result_.report.push_back(verdict);
  }

  void subsystem(const Block& block, const std::string& block_path, const Workspace& outer,
                 const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                 const std::vector<std::string>& enables, const Trigger& trigger, std::vector<DuetBlock>& blocks,
                 Names& names, Names& signals, Verdict& verdict) {
    const std::string kind = block.parameters.count("SFBlockType") ? block.parameters.at("SFBlockType") : "NONE";
    if (kind != "NONE") {
      verdict.what = "a " + kind + " block: its code is MATLAB or Stateflow, which duet does not translate";
      refuse(verdict);
      return;
    }
    if (block.systems.empty()) {
      verdict.what = "a subsystem without contents (a reference to another file?)";
      refuse(verdict);
      return;
    }
    // A masked subsystem's parameters, evaluated outside it, are variables inside it.
    Workspace inner = outer;
    for (const auto& [name, text] : block.mask_parameters) {
      auto value = evaluate(text, outer);
      if (!value) {
        verdict.what = "mask parameter " + name + " '" + text + "': " + value.error();
        refuse(verdict);
        return;
      }
      inner.insert_or_assign(name, std::move(value).value());
    }
    DuetBlock made{.name = names.unique(identifier(block.name)), .type = "Subsystem"};
    made.source = block_path + " (SubSystem)";
    TextPairs inner_inputs;
    TextPairs inner_outputs;
    made.blocks = import_system(block.systems[0], block_path, inner, false, &inner_inputs, &inner_outputs);
    for (std::size_t port = 0; port < inner_inputs.size(); ++port) {
      if (port >= inputs.size() || inputs[port].empty()) {
        verdict.what = "its input " + std::to_string(port + 1) + " is not connected";
        refuse(verdict);
        return;
      }
      if (!inner_inputs[port].first.empty()) made.inputs.emplace_back(inner_inputs[port].first, inputs[port]);
    }
    for (std::size_t port = 0; port < inner_outputs.size(); ++port) {
      if (port < outputs.size() && !outputs[port].empty() && !inner_outputs[port].first.empty())
        made.outputs.emplace_back(inner_outputs[port].first, outputs[port]);
    }
    if (!trigger_and_enable(block, block_path, enables, trigger, made, verdict)) return;
    if (!made.enable.empty()) {
      // Simulink enables a subsystem while its enable signal is positive; duet's enable is one boolean.
      const std::string enabled = signals.unique(made.name + "_enabled");
      blocks.push_back({.name = names.unique(made.name + "_enabled"),
                        .type = "Compare",
                        .parameters = {{"operator", "\">\""}, {"value", "0"}},
                        .inputs = {{"u", made.enable}},
                        .outputs = {{"y", enabled}},
                        .source = block_path + " (SubSystem): enabled while its enable signal is positive"});
      made.enable = enabled;
    }
    verdict.imported = true;
    verdict.what = "Subsystem" + (made.trigger.empty() ? std::string{} : " triggered " + made.trigger) +
                   (made.enable.empty() ? std::string{} : " enabled by " + made.enable);
    result_.report.push_back(verdict);
    blocks.push_back(std::move(made));
  }

  bool trigger_and_enable(const Block& block, const std::string& block_path, const std::vector<std::string>& enables,
                          const Trigger& trigger, DuetBlock& made, Verdict& verdict) {
    for (const Block& inside : block.systems[0].blocks) {
      const auto setting = [&inside](const char* name, const char* otherwise) {
        return stored_or(inside, name, otherwise);
      };
      if (inside.type == "EnablePort") {
        if (setting("StatesWhenEnabling", "held") != "held" || setting("ShowOutputPort", "off") != "off") {
          verdict.what = "its enable port resets states or shows an output, which duet's enabled subsystems do not";
          refuse(verdict);
          return false;
        }
        if (enables.empty() || enables[0].empty()) {
          verdict.what = "its enable port is not connected";
          refuse(verdict);
          return false;
        }
        made.enable = enables[0];
      }
      if (inside.type == "TriggerPort") {
        const std::string type = setting("TriggerType", "rising");
        if (type == "function-call") {
          const auto mapped = options_.interrupts.find(block_path);
          if (mapped == options_.interrupts.end()) {
            verdict.what =
                "a function-call subsystem: map it to an interrupt with --interrupt '" + block_path + "=IRQ:PRIORITY'";
            refuse(verdict);
            return false;
          }
          made.trigger = "{interrupt: " + mapped->second.interrupt +
                         ", priority: " + std::to_string(mapped->second.priority) + "}";
          continue;
        }
        if (setting("InitialTriggerSignalState", "compatibility (no trigger on first evaluation)") != "zero") {
          verdict.what =
              "its trigger's InitialTriggerSignalState is not 'zero': duet's edge detection starts from "
              "zero (set it to zero in Simulink)";
          refuse(verdict);
          return false;
        }
        if (trigger.signals.empty() || trigger.signals[0].empty()) {
          verdict.what = "its trigger port is not connected";
          refuse(verdict);
          return false;
        }
        if (trigger.driver == nullptr || !never_negative(*trigger.driver, trigger.in_root)) {
          verdict.what =
              "its trigger signal " + trigger.signals[0] +
              (trigger.driver == nullptr ? std::string{}
                                         : " (from " + trigger.driver->name + ", " + trigger.driver->type + ")") +
              " may be negative, and then Simulink's edges and duet's differ (Simulink also triggers on a rise "
              "from below zero to exactly zero); trigger with a boolean or unsigned signal (a Compare To Zero, a "
              "Relational Operator, an Inport of type boolean) so that both agree";
          refuse(verdict);
          return false;
        }
        made.trigger = "{edge: " + type + ", signal: " + trigger.signals[0] + "}";
      }
    }
    return true;
  }

  const SimulinkModel& model_;
  const ImportOptions& options_;
  ImportResult result_;
  DuetModel duet_;
  long long base_period_us_ = 0;
  std::set<std::string> parameter_names_;
};

}  // namespace

ImportResult import_simulink(const SimulinkModel& model, const ImportOptions& options) {
  return Importer{model, options}.run();
}

std::vector<std::string> integer_problems(const ImportResult& result,
                                          const std::function<std::string(const std::string& block)>& output_type) {
  std::vector<std::string> problems;
  for (const FloatingOnly& each : result.floating_only) {
    const std::string type = output_type(each.block);
    if (type.starts_with("int") || type.starts_with("uint"))
      problems.push_back(each.source + ": it computes in " + type + ": " + each.why);
  }
  return problems;
}

}  // namespace duet::simulink_import
