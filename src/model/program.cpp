#include "duet/model/program.hpp"

#include <algorithm>
#include <set>
#include <tuple>

#include "duet/model/block_types.hpp"
#include "duet/model/data_type.hpp"
#include "duet/model/validate.hpp"
#include "flat_model.hpp"
#include "typing.hpp"

namespace duet::model {

std::size_t SignalType::elements() const {
  std::size_t count = 1;
  for (const std::size_t dimension : shape) count *= dimension;
  return count;
}

std::string describe(const SignalType& type) {
  std::string text{type_name(type.type)};
  if (type.shape.size() == 1) text += "[" + std::to_string(type.shape[0]) + "]";
  if (type.shape.size() == 2) text += "[" + std::to_string(type.shape[0]) + "x" + std::to_string(type.shape[1]) + "]";
  return text;
}

const Argument* ProgramBlock::argument(const std::string& name) const {
  const auto found = arguments.find(name);
  return found == arguments.end() ? nullptr : &found->second;
}

std::optional<std::size_t> Program::find_signal(const std::string& name) const {
  for (std::size_t index = 0; index < signals.size(); ++index) {
    if (signals[index].name == name) return index;
  }
  return std::nullopt;
}

namespace {

std::string identifier_of(const std::string& path) {
  std::string text = path;
  std::replace(text.begin(), text.end(), '/', '_');
  return text;
}

// "u10" after "u9": numbered ports by their number, others in the order the type names them; a Code block's ports as
// the model lists them (its function takes a structure of them, whatever their names).
std::vector<std::size_t> port_order(const Block& block, const std::vector<std::string_view>& declared) {
  std::vector<std::size_t> order(block.inputs.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  if (block.code) return order;
  // (group, number of digits, digits): compares numbers of any length without converting them.
  const auto rank = [&](std::size_t k) -> std::tuple<std::size_t, std::size_t, std::string> {
    const std::string& port = block.inputs[k].port;
    const auto named = std::find(declared.begin(), declared.end(), port);
    if (named != declared.end()) return {static_cast<std::size_t>(named - declared.begin()), 0, {}};
    const bool numbered = port.size() > 1 && port[0] == 'u' &&
                          std::all_of(port.begin() + 1, port.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (numbered) return {declared.size(), port.size(), port};
    return {declared.size() + 1, k, {}};
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
  return order;
}

class ProgramBuilder {
 public:
  explicit ProgramBuilder(const Model& model) : model_(model), flat_(model), rates_(analyse_rates(model)) {
    program_.model = &model;
    program_.implied_blocks = flat_.implied_blocks;
  }

  ProgramBuild build(std::vector<Diagnostic> diagnostics) {
    add_blocks();
    type_signals();
    for (const ProgramBlock& block : program_.blocks) check_types(program_, block, diagnostics);
    check_declarations(diagnostics);
    check_subsystems(model_.blocks, "", 0, diagnostics);
    if (!has_errors(diagnostics)) check_loops(diagnostics);
    if (has_errors(diagnostics)) return {std::nullopt, std::move(diagnostics)};
    lay_out_tasks(diagnostics);
    check_rate_transitions(diagnostics);
    if (has_errors(diagnostics)) return {std::nullopt, std::move(diagnostics)};
    return {std::move(program_), std::move(diagnostics)};
  }

 private:
  void add_blocks() {
    std::map<std::string, std::size_t> signal_of;
    for (std::size_t driver = 0; driver < flat_.nodes.size(); ++driver) {
      for (const std::string& output : flat_.nodes[driver].outputs) {
        ProgramSignal signal;
        signal.name = flat_.outermost_name(output);
        signal.identifier = identifier_of(signal.name);
        signal.driver = driver;
        for (const SignalDeclaration& declaration : model_.signals) {
          if (declaration.name != signal.name) continue;
          signal.unit = declaration.unit;
          signal.description = declaration.description;
          signal.measurable = declaration.measurable;
          signal.labels = declaration.labels;
        }
        signal_of[output] = program_.signals.size();
        program_.signals.push_back(signal);
      }
    }
    for (const Node& node : flat_.nodes) {
      ProgramBlock block;
      block.path = node.path;
      block.identifier = identifier_of(node.path);
      block.block = node.block;
      const BlockType* type = find_block_type(node.block->type);
      std::vector<std::string_view> declared = type != nullptr ? type->inputs : std::vector<std::string_view>{};
      if (type != nullptr) declared.insert(declared.end(), type->optional_inputs.begin(), type->optional_inputs.end());
      for (const std::size_t k : port_order(*node.block, declared)) {
        block.inputs.push_back(signal_of.at(node.inputs[k].signal));
        block.input_ports.push_back(node.block->inputs[k].port);
      }
      for (std::size_t k = 0; k < node.outputs.size(); ++k) {
        block.outputs.push_back(signal_of.at(node.outputs[k]));
        block.output_ports.push_back(node.block->outputs[k].port);
      }
      for (const std::string& enable : node.enables) block.enables.push_back(signal_of.at(enable));
      for (const auto& [name, parameter] : node.block->parameters) block.arguments[name] = resolve(name, parameter);
      const Argument* value = block.argument("value");
      if (block.type() == "Constant" && value != nullptr && value->kind == Argument::Kind::parameter &&
          !block.outputs.empty()) {
        program_.signals[block.outputs[0]].parameter = value->parameter;
      }
      program_.blocks.push_back(std::move(block));
    }
  }

  Argument resolve(const std::string& name, const BlockParameter& parameter) const {
    Argument argument;
    argument.text = parameter.text;
    argument.location = parameter.location;
    if (parameter.literal) {
      argument.value = *parameter.literal;
      return argument;
    }
    if (parameter.reference.empty() || is_word_parameter(name)) {
      argument.kind = Argument::Kind::word;
      return argument;
    }
    for (std::size_t index = 0; index < model_.parameters.size(); ++index) {
      if (model_.parameters[index].name != parameter.reference) continue;
      argument.kind = Argument::Kind::parameter;
      argument.parameter = index;
      argument.value = model_.parameters[index].value;
      return argument;
    }
    for (const Constant& constant : model_.constants) {
      if (constant.name == parameter.reference) argument.value = constant.value;
    }
    return argument;
  }

  // Types flow from drivers to readers until nothing changes. In a loop where every block waits for another, the
  // signals the model declares seed it; then blocks whose output type does not depend on their input's guess it is a
  // scalar (typing.hpp); a signal no rule reaches is a double. check_loops() checks what seeds and guesses gave.
  void type_signals() {
    known_.assign(program_.signals.size(), std::nullopt);
    bool guess_scalars = false;
    for (bool changed = true; changed;) {
      changed = false;
      for (const ProgramBlock& block : program_.blocks) {
        const KnownTypes outputs = infer_outputs(program_, block, known_inputs(block), guess_scalars);
        for (std::size_t k = 0; k < outputs.size(); ++k) {
          if (outputs[k] && !known_[block.outputs[k]]) {
            known_[block.outputs[k]] = outputs[k];
            changed = true;
          }
        }
      }
      if (changed) {
        guess_scalars = false;
      } else if (seed_declarations()) {
        changed = true;
      } else if (!guess_scalars) {
        guess_scalars = true;
        changed = true;
      }
    }
    for (std::size_t index = 0; index < known_.size(); ++index) {
      program_.signals[index].type = known_[index].value_or(SignalType{});
    }
  }

  [[nodiscard]] KnownTypes known_inputs(const ProgramBlock& block) const {
    KnownTypes inputs;
    for (const std::size_t input : block.inputs) inputs.push_back(known_[input]);
    return inputs;
  }

  // Gives the declared signals that nothing has typed yet their declared type; whether there were any.
  bool seed_declarations() {
    bool seeded = false;
    for (const SignalDeclaration& declaration : model_.signals) {
      const auto index = program_.find_signal(declaration.name);
      if (!index || known_[*index] || !declaration.type) continue;
      known_[*index] = SignalType{*declaration.type, declaration.shape};
      seeded = true;
    }
    return seeded;
  }

  // Every block's outputs must be what its inputs make of them, also where a loop was seeded or guessed before its
  // inputs were known.
  void check_loops(std::vector<Diagnostic>& diagnostics) const {
    for (const ProgramBlock& block : program_.blocks) {
      KnownTypes inputs;
      for (const std::size_t input : block.inputs) inputs.push_back(program_.signals[input].type);
      const KnownTypes outputs = infer_outputs(program_, block, inputs, false);
      for (std::size_t k = 0; k < outputs.size(); ++k) {
        const ProgramSignal& signal = program_.signals[block.outputs[k]];
        if (!outputs[k] || *outputs[k] == signal.type) continue;
        const auto declared = std::find_if(model_.signals.begin(), model_.signals.end(),
                                           [&signal](const SignalDeclaration& d) { return d.name == signal.name; });
        if (declared != model_.signals.end() && declared->type) {
          diagnostics.push_back({Diagnostic::Severity::error, declared->location,
                                 "type mismatch: signal '" + signal.name + "' is declared " + describe(signal.type) +
                                     " but block '" + block.path + "' (" + block.type() + ") drives it with " +
                                     describe(*outputs[k]),
                                 "declare it as " + describe(*outputs[k]) + ", or convert it with a Convert block"});
        } else {
          diagnostics.push_back(
              {Diagnostic::Severity::error, block.block->outputs[k].location,
               "type mismatch: block '" + block.path + "' (" + block.type() + ") drives signal '" + signal.name +
                   "' with " + describe(*outputs[k]) + ", but the loop it is in was taken for " +
                   describe(signal.type) + " before its inputs were known",
               "a loop gives each signal one type and size all the way round; if this one does, declare it: "
               "signals: {" +
                   signal.name + ": " + declaration_of(*outputs[k]) + "}"});
        }
        return;  // one is enough: the rest of the loop follows from it
      }
    }
  }

  // Between periodic rates a transfer is deterministic and needs rates that are multiples of each other; with an
  // interrupt task on either side it hands over the latest value. `mode` may say which, and must not contradict it.
  void check_rate_transitions(std::vector<Diagnostic>& diagnostics) const {
    for (const ProgramBlock& block : program_.blocks) {
      if (block.type() != "RateTransition" || block.task == at_initialisation ||
          block.update_task == at_initialisation) {
        continue;
      }
      const Rate& from = program_.tasks[block.update_task].rate;
      const Rate& to = program_.tasks[block.task].rate;
      const Argument* mode = block.argument("mode");
      const std::string name = "RateTransition '" + block.path + "'";
      const double base = model_.base_period_us;
      if (from.kind == Rate::Kind::periodic && to.kind == Rate::Kind::periodic) {
        const std::int64_t fast = std::min(from.multiple, to.multiple);
        const std::int64_t slow = std::max(from.multiple, to.multiple);
        if (slow % fast != 0) {
          diagnostics.push_back({Diagnostic::Severity::error, block.block->location,
                                 name + " joins rates of " + describe(from, base) + " and " + describe(to, base) +
                                     ", which are not multiples of each other",
                                 "make the slower period a multiple of the faster, or pass the value through a "
                                 "rate both divide"});
        }
        if (mode != nullptr && mode->text == "latest") {
          diagnostics.push_back({Diagnostic::Severity::error, mode->location,
                                 name + " joins two periodic rates, where the transfer is deterministic",
                                 "write mode: deterministic, or leave mode out; latest is for interrupt tasks"});
        }
      } else if (mode != nullptr && mode->text == "deterministic") {
        diagnostics.push_back({Diagnostic::Severity::error, mode->location,
                               name + " joins " + describe(from, base) + " and " + describe(to, base) +
                                   ", which share no time base: it cannot be deterministic",
                               "write mode: latest, or leave mode out"});
      }
    }
  }

  static std::string declaration_of(const SignalType& type) {
    std::string text = "{type: " + std::string{type_name(type.type)};
    if (type.shape.size() == 1) text += ", size: " + std::to_string(type.shape[0]);
    if (type.shape.size() == 2) {
      text += ", size: [" + std::to_string(type.shape[0]) + ", " + std::to_string(type.shape[1]) + "]";
    }
    return text + "}";
  }

  // An enabling signal is one boolean. `enables` counts the enabling signals around `blocks` (an enabled subsystem's,
  // then an edge-triggered one's detector output, as FlatModel adds them).
  void check_subsystems(const std::vector<Block>& blocks, const std::string& prefix, std::size_t enables,
                        std::vector<Diagnostic>& diagnostics) const {
    for (const Block& block : blocks) {
      if (block.type != "Subsystem") continue;
      const std::string path = prefix + block.name;
      const std::size_t inner =
          enables + (block.enable.empty() ? 0 : 1) + (block.trigger.kind == Trigger::Kind::edge ? 1 : 0);
      if (!block.enable.empty()) {
        const auto member = std::find_if(program_.blocks.begin(), program_.blocks.end(), [&](const ProgramBlock& b) {
          return b.path.rfind(path + "/", 0) == 0 && b.enables.size() >= inner;
        });
        if (member != program_.blocks.end()) {
          const ProgramSignal& signal = program_.signals[member->enables[enables]];
          if (signal.type != SignalType{DataType::boolean, {}}) {
            diagnostics.push_back({Diagnostic::Severity::error, block.location,
                                   "type mismatch: subsystem '" + path + "' is enabled by signal '" + signal.name +
                                       "', which is " + describe(signal.type),
                                   "an enabling signal is one boolean: make it with a Compare block"});
          }
        }
      }
      check_subsystems(block.blocks, path + "/", inner, diagnostics);
    }
  }

  // Declared types must be what the driver produces; no conversion is silent.
  void check_declarations(std::vector<Diagnostic>& diagnostics) const {
    for (const SignalDeclaration& declaration : model_.signals) {
      const auto index = program_.find_signal(declaration.name);
      if (!index) continue;
      const ProgramSignal& signal = program_.signals[*index];
      const SignalType declared{declaration.type.value_or(signal.type.type),
                                declaration.shape.empty() ? signal.type.shape : declaration.shape};
      if (declared == signal.type) continue;
      const ProgramBlock& driver = program_.blocks[signal.driver];
      diagnostics.push_back({Diagnostic::Severity::error, declaration.location,
                             "type mismatch: signal '" + declaration.name + "' is declared " + describe(declared) +
                                 " but block '" + driver.path + "' (" + driver.type() + ") drives it with " +
                                 describe(signal.type),
                             "declare it as " + describe(signal.type) + ", or convert it with a Convert block"});
    }
    std::map<std::string, std::string> seen;  // identifier -> signal
    for (const ProgramSignal& signal : program_.signals) {
      const auto [found, added] = seen.emplace(signal.identifier, signal.name);
      if (!added) {
        diagnostics.push_back({Diagnostic::Severity::error, program_.blocks[signal.driver].block->location,
                               "signals '" + found->second + "' and '" + signal.name + "' both become '" +
                                   signal.identifier + "' in generated code",
                               "rename one of them"});
      }
    }
  }

  void lay_out_tasks(std::vector<Diagnostic>& diagnostics) {
    std::map<std::string, std::size_t> block_of;
    for (std::size_t index = 0; index < program_.blocks.size(); ++index) block_of[program_.blocks[index].path] = index;
    std::vector<Task> tasks = rates_.tasks;
    std::vector<std::string> constants;
    move_tunable_constants(block_of, tasks, constants);
    for (const Task& task : tasks) {
      ProgramTask laid_out{task.name, task.rate, task.priority, {}, {}};
      const std::size_t task_index = program_.tasks.size();
      for (const std::string& path : task.blocks) {
        ProgramBlock& block = program_.blocks[block_of.at(path)];
        block.task = task_index;
        block.update_task = task_index;
        block.period_s = task.rate.kind == Rate::Kind::periodic ? task.period_us * 1e-6 : 0.0;
        laid_out.outputs.push_back(block_of.at(path));
      }
      program_.tasks.push_back(std::move(laid_out));
    }
    for (const std::string& path : constants) {
      program_.blocks[block_of.at(path)].task = at_initialisation;
      program_.blocks[block_of.at(path)].update_task = at_initialisation;
      // Computed once, before anything runs: a constant in an enabled or triggered subsystem is that constant.
      program_.blocks[block_of.at(path)].enables.clear();
      program_.initial_outputs.push_back(block_of.at(path));
    }
    // A RateTransition takes its value in the task of what drives it.
    for (ProgramBlock& block : program_.blocks) {
      if (block.type() != "RateTransition" || block.inputs.empty()) continue;
      const std::size_t driver = program_.signals[block.inputs[0]].driver;
      block.update_task = program_.blocks[driver].task;
      if (block.update_task == at_initialisation) {  // it would never take the value
        diagnostics.push_back({Diagnostic::Severity::error, block.block->location,
                               "block '" + block.path + "' (RateTransition) reads signal '" +
                                   program_.signals[block.inputs[0]].name + "' of block '" +
                                   program_.blocks[driver].path + "', a constant",
                               "every rate reads a constant directly: remove the RateTransition"});
      }
    }
    for (std::size_t index = 0; index < program_.blocks.size(); ++index) {
      const std::size_t task = program_.blocks[index].update_task;
      if (task != at_initialisation) program_.tasks[task].updates.push_back(index);
    }
  }

  // Constant blocks that read a tunable parameter (or are enabled by one), directly or through other constant blocks,
  // must see it change like every other reader: they run first in the base-rate task. The rest stay `constants`,
  // computed once. A Constant naming the parameter is the parameter itself. Every program gets a base-rate task, even
  // an empty one: the executive's task table starts with it (duet/rt/task_table.hpp).
  void move_tunable_constants(const std::map<std::string, std::size_t>& block_of, std::vector<Task>& tasks,
                              std::vector<std::string>& constants) const {
    std::set<std::size_t> tunable;  // signals
    for (std::size_t index = 0; index < program_.signals.size(); ++index) {
      if (program_.signals[index].parameter) tunable.insert(index);
    }
    std::vector<std::string> moved;
    for (const std::string& path : rates_.constant_blocks) {  // in execution order: what a block reads comes first
      const ProgramBlock& block = program_.blocks[block_of.at(path)];
      const bool is_parameter = !block.outputs.empty() && program_.signals[block.outputs[0]].parameter;
      const bool reads_parameter = std::any_of(block.arguments.begin(), block.arguments.end(), [](const auto& entry) {
        return entry.second.kind == Argument::Kind::parameter;
      });
      const auto is_tunable = [&tunable](std::size_t signal) { return tunable.count(signal) != 0; };
      const bool reads_tunable = std::any_of(block.inputs.begin(), block.inputs.end(), is_tunable) ||
                                 std::any_of(block.enables.begin(), block.enables.end(), is_tunable);
      if (is_parameter || !(reads_parameter || reads_tunable)) {
        constants.push_back(path);
        continue;
      }
      moved.push_back(path);
      tunable.insert(block.outputs.begin(), block.outputs.end());
    }
    // The executive's task table starts with the base rate (duet/rt/task_table.hpp), even when no block runs there.
    if (tasks.empty() || tasks.front().rate != Rate{Rate::Kind::periodic, 1, {}}) {
      tasks.insert(tasks.begin(), Task{"rate 1", {Rate::Kind::periodic, 1, {}}, model_.base_period_us, {}, {}});
    }
    if (moved.empty()) return;
    tasks.front().blocks.insert(tasks.front().blocks.begin(), moved.begin(), moved.end());
  }

  const Model& model_;
  FlatModel flat_;
  RateAnalysis rates_;
  Program program_;
  std::vector<std::optional<SignalType>> known_;  // while typing the signals
};

}  // namespace

ProgramBuild build_program(const Model& model) {
  std::vector<Diagnostic> diagnostics = validate(model);
  if (has_errors(diagnostics)) return {std::nullopt, std::move(diagnostics)};
  return ProgramBuilder{model}.build(std::move(diagnostics));
}

}  // namespace duet::model
