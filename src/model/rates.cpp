#include "duet/model/rates.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "duet/model/block_types.hpp"
#include "flat_model.hpp"

namespace duet::model {
namespace {

// The nodes of one task, in an order where each block's direct-feedthrough inputs are computed before it; ties in
// model order. A cycle (an algebraic loop, which validation reports) leaves its blocks in model order at the end.
std::vector<std::string> execution_order(const FlatModel& flat, const std::vector<std::size_t>& members,
                                         const std::map<std::string, std::size_t>& driver_of) {
  std::map<std::size_t, std::vector<std::size_t>> next;
  std::map<std::size_t, int> waiting;  // inputs from the same task not computed yet
  for (const std::size_t member : members) waiting[member] = 0;
  for (const std::size_t reader : members) {
    const Block& block = *flat.nodes[reader].block;
    const BlockType* type = find_block_type(block.type);
    const bool feedthrough = block.code ? block.code->direct_feedthrough : type == nullptr || type->direct_feedthrough;
    if (!feedthrough) continue;
    for (const Input& input : flat.nodes[reader].inputs) {
      const auto driver = driver_of.find(input.signal);
      if (driver == driver_of.end() || waiting.count(driver->second) == 0 || driver->second == reader) continue;
      next[driver->second].push_back(reader);
      ++waiting[reader];
    }
  }
  // Whatever enables a block (an enabled or triggered subsystem) is computed before it, feedthrough or not.
  for (const std::size_t reader : members) {
    for (const std::string& enable : flat.nodes[reader].enables) {
      const auto driver = driver_of.find(enable);
      if (driver == driver_of.end() || waiting.count(driver->second) == 0 || driver->second == reader) continue;
      next[driver->second].push_back(reader);
      ++waiting[reader];
    }
  }
  std::set<std::size_t> ready;
  for (const auto& [member, count] : waiting) {
    if (count == 0) ready.insert(member);
  }
  std::vector<std::string> order;
  std::set<std::size_t> placed;
  while (!ready.empty()) {
    const std::size_t node = *ready.begin();  // the earliest in the model
    ready.erase(ready.begin());
    order.push_back(flat.nodes[node].path);
    placed.insert(node);
    for (const std::size_t reader : next[node]) {
      if (--waiting[reader] == 0) ready.insert(reader);
    }
  }
  for (const std::size_t member : members) {
    if (placed.count(member) == 0) order.push_back(flat.nodes[member].path);
  }
  return order;
}

Rate declared(const Node& node) {
  if (!node.interrupt.empty()) return {Rate::Kind::interrupt, 0, node.interrupt};
  switch (node.block->period.kind) {
    case Period::Kind::base: return {Rate::Kind::periodic, 1, {}};
    case Period::Kind::multiple: return {Rate::Kind::periodic, node.block->period.multiple, {}};
    case Period::Kind::constant: return {Rate::Kind::constant, 0, {}};
    case Period::Kind::inherited: break;
  }
  if (node.block->type == "Constant") return {Rate::Kind::constant, 0, {}};
  if (node.inputs.empty() && node.enables.empty()) return {Rate::Kind::periodic, 1, {}};  // a source: the base rate
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
  FlatModel flat{model};
  std::map<std::string, std::size_t> driver_of;  // resolved signal -> node
  for (std::size_t i = 0; i < flat.nodes.size(); ++i) {
    for (const std::string& output : flat.nodes[i].outputs) driver_of.emplace(output, i);
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
      std::vector<Input> sources = node.inputs;  // what it reads: its inputs and what enables it
      for (const std::string& enable : node.enables) sources.push_back({enable, node.block->location});
      for (const Input& input : sources) {
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
        // A source enabled by a constant is still a source: it runs at the base rate, not once.
        node.rate = node.inputs.empty() ? Rate{Rate::Kind::periodic, 1, {}} : Rate{Rate::Kind::constant, 0, {}};
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
    if (node.block->type == "RateTransition") {  // it is where rates may meet; where none do, say so
      const auto driver = node.inputs.empty() ? driver_of.end() : driver_of.find(node.inputs[0].signal);
      if (driver != driver_of.end() && flat.nodes[driver->second].rate == node.rate &&
          node.rate.kind == Rate::Kind::periodic) {
        result.diagnostics.push_back({Diagnostic::Severity::warning, node.block->location,
                                      "RateTransition '" + node.path + "' has the same rate on both sides (" +
                                          describe(node.rate, model.base_period_us) + "): it only delays by one step",
                                      "give the blocks it feeds a period of their own, e.g. period: {multiple: 10}"});
      }
      continue;
    }
    std::vector<Input> sources = node.inputs;
    // A constant is computed once, before anything runs: what would enable it does not matter.
    if (node.rate.kind != Rate::Kind::constant) {
      for (const std::string& enable : node.enables) sources.push_back({enable, node.block->location});
    }
    for (const Input& input : sources) {
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
  for (Task& task : result.tasks) {
    std::vector<std::size_t> members;
    for (std::size_t i = 0; i < flat.nodes.size(); ++i) {
      if (flat.nodes[i].rate == task.rate) members.push_back(i);
    }
    task.blocks = execution_order(flat, members, driver_of);
  }
  std::vector<std::size_t> constants;
  for (std::size_t i = 0; i < flat.nodes.size(); ++i) {
    if (flat.nodes[i].rate.kind == Rate::Kind::constant) constants.push_back(i);
  }
  result.constant_blocks = execution_order(flat, constants, driver_of);
  return result;
}

}  // namespace duet::model
