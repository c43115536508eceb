#include "duet/model/rates.hpp"

#include <algorithm>
#include <set>
#include <sstream>

namespace duet::model {
namespace {

struct Input {
  std::string signal;  // global name, resolved
  Location location;
};

// A block of the flattened model.
struct Node {
  std::string path;
  const Block* block;
  std::string interrupt;  // the interrupt task it runs in, if inside a triggered subsystem
  std::vector<Input> inputs;
  std::vector<std::string> outputs;
  Rate rate;
};

class Flattener {
 public:
  std::vector<Node> nodes;
  std::map<std::string, std::string> aliases;  // a subsystem's port signal -> the signal it stands for

  void scope(const std::vector<Block>& blocks, const std::string& prefix, const std::string& interrupt) {
    for (const Block& block : blocks) {
      const std::string path = prefix + block.name;
      if (block.type == "Subsystem") {
        const std::string inner = path + "/";
        const std::string task = block.trigger.kind == Trigger::Kind::interrupt ? block.trigger.interrupt : interrupt;
        for (const Connection& input : block.inputs) aliases[inner + input.port] = prefix + input.signal;
        for (const Connection& output : block.outputs) aliases[prefix + output.signal] = inner + output.port;
        scope(block.blocks, inner, task);
        continue;
      }
      Node node{path, &block, interrupt, {}, {}, {}};
      for (const Connection& input : block.inputs) node.inputs.push_back({prefix + input.signal, input.location});
      for (const Connection& output : block.outputs) node.outputs.push_back(prefix + output.signal);
      nodes.push_back(std::move(node));
    }
  }

  [[nodiscard]] std::string resolve(std::string signal) const {
    for (std::size_t step = 0; step < aliases.size() + 1; ++step) {  // bounded: aliases cannot cycle forever
      const auto found = aliases.find(signal);
      if (found == aliases.end()) return signal;
      signal = found->second;
    }
    return signal;
  }
};

Rate declared(const Node& node) {
  if (!node.interrupt.empty()) return {Rate::Kind::interrupt, 0, node.interrupt};
  switch (node.block->period.kind) {
    case Period::Kind::base: return {Rate::Kind::periodic, 1, {}};
    case Period::Kind::multiple: return {Rate::Kind::periodic, node.block->period.multiple, {}};
    case Period::Kind::constant: return {Rate::Kind::constant, 0, {}};
    case Period::Kind::inherited: break;
  }
  if (node.block->type == "Constant") return {Rate::Kind::constant, 0, {}};
  if (node.inputs.empty()) return {Rate::Kind::periodic, 1, {}};  // a source: the base rate
  return {};
}

}  // namespace

std::string describe(const Rate& rate, double base_period_us) {
  std::ostringstream text;
  switch (rate.kind) {
    case Rate::Kind::periodic: text << static_cast<double>(rate.multiple) * base_period_us << " us"; break;
    case Rate::Kind::interrupt: text << "interrupt " << rate.interrupt; break;
    case Rate::Kind::constant: text << "constant"; break;
    case Rate::Kind::unknown: text << "unknown"; break;
  }
  return text.str();
}

RateAnalysis analyse_rates(const Model& model) {
  Flattener flat;
  flat.scope(model.blocks, "", "");
  std::map<std::string, std::size_t> driver_of;  // resolved signal -> node
  for (std::size_t i = 0; i < flat.nodes.size(); ++i) {
    for (std::string& output : flat.nodes[i].outputs) {
      output = flat.resolve(output);
      driver_of.emplace(output, i);
    }
    for (Input& input : flat.nodes[i].inputs) input.signal = flat.resolve(input.signal);
    flat.nodes[i].rate = declared(flat.nodes[i]);
  }
  const auto rate_of_driver = [&](const Input& input) -> Rate {
    const auto driver = driver_of.find(input.signal);
    return driver == driver_of.end() ? Rate{} : flat.nodes[driver->second].rate;
  };
  // Inherited rates flow from inputs to outputs until nothing changes; what stays open (a loop of inherited blocks)
  // runs at the base rate.
  for (bool changed = true; changed;) {
    changed = false;
    for (Node& node : flat.nodes) {
      if (node.rate.kind != Rate::Kind::unknown || node.block->type == "RateTransition") continue;
      bool all_constant = true;
      bool open = false;
      for (const Input& input : node.inputs) {
        const Rate rate = rate_of_driver(input);
        if (rate.kind == Rate::Kind::unknown) open = true;
        if (rate.kind != Rate::Kind::constant && rate.kind != Rate::Kind::unknown) {
          node.rate = rate;  // the first input's; a different rate on another input is a crossing, reported below
          changed = true;
          break;
        }
        all_constant = all_constant && rate.kind == Rate::Kind::constant;
      }
      if (node.rate.kind == Rate::Kind::unknown && !open && all_constant) {
        node.rate = {Rate::Kind::constant, 0, {}};
        changed = true;
      }
    }
  }
  for (Node& node : flat.nodes) {
    if (node.rate.kind == Rate::Kind::unknown && node.block->type != "RateTransition") {
      node.rate = {Rate::Kind::periodic, 1, {}};
    }
  }
  // A RateTransition without a period of its own runs at the rate of what reads it.
  for (Node& node : flat.nodes) {
    if (node.block->type != "RateTransition" || node.rate.kind != Rate::Kind::unknown) continue;
    for (const Node& reader : flat.nodes) {
      for (const Input& input : reader.inputs) {
        if (std::find(node.outputs.begin(), node.outputs.end(), input.signal) != node.outputs.end() &&
            node.rate.kind == Rate::Kind::unknown) {
          node.rate = reader.rate;
        }
      }
    }
    if (node.rate.kind == Rate::Kind::unknown) node.rate = {Rate::Kind::periodic, 1, {}};
  }

  RateAnalysis result;
  for (const Node& node : flat.nodes) {
    result.block_rates[node.path] = node.rate;
    if (node.block->type == "RateTransition") continue;  // it is where rates may meet
    for (const Input& input : node.inputs) {
      const auto driver = driver_of.find(input.signal);
      if (driver == driver_of.end()) continue;  // undriven: validation says so
      const Node& source = flat.nodes[driver->second];
      if (source.rate.kind == Rate::Kind::constant || source.rate == node.rate) continue;
      const std::string signal = input.signal.substr(input.signal.rfind('/') + 1);
      if (node.rate.kind == Rate::Kind::interrupt && source.rate.kind == Rate::Kind::periodic) {
        result.diagnostics.push_back({Diagnostic::Severity::error, input.location,
                                      "the interrupt task '" + node.rate.interrupt + "' reads signal '" + signal +
                                          "' of the periodic block '" + source.path + "' (" +
                                          describe(source.rate, model.base_period_us) + ") directly",
                                      "put a RateTransition (mode: latest) between them"});
      } else {
        result.diagnostics.push_back({Diagnostic::Severity::error, input.location,
                                      "rate crossing: block '" + node.path + "' (" +
                                          describe(node.rate, model.base_period_us) + ") reads signal '" + signal +
                                          "' of block '" + source.path + "' (" +
                                          describe(source.rate, model.base_period_us) + ") directly",
                                      "put a RateTransition between them"});
      }
    }
  }
  std::set<std::int64_t> multiples;
  for (const Node& node : flat.nodes) {
    if (node.rate.kind == Rate::Kind::periodic) multiples.insert(node.rate.multiple);
  }
  for (const std::int64_t multiple : multiples) {
    result.tasks.push_back({"rate " + std::to_string(multiple),
                            {Rate::Kind::periodic, multiple, {}},
                            static_cast<double>(multiple) * model.base_period_us,
                            std::nullopt});
  }
  // Interrupt tasks, from the triggered subsystems (also those with no block inside).
  const auto interrupts = [&](const auto& self, const std::vector<Block>& blocks) -> void {
    for (const Block& block : blocks) {
      if (block.type != "Subsystem") continue;
      if (block.trigger.kind == Trigger::Kind::interrupt) {
        result.tasks.push_back(
            {block.trigger.interrupt, {Rate::Kind::interrupt, 0, block.trigger.interrupt}, 0, block.trigger.priority});
      }
      self(self, block.blocks);
    }
  };
  interrupts(interrupts, model.blocks);
  return result;
}

}  // namespace duet::model
