#pragma once
// For the model's passes (private to src/model): the model flattened into blocks with resolved signal names. A
// subsystem's ports stand for the parent's signals; blocks inside a triggered subsystem belong to its interrupt task.

#include <algorithm>
#include <cstddef>
#include <deque>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "duet/model/model.hpp"
#include "duet/model/rates.hpp"

namespace duet::model {

struct Input {
  std::string signal;  // global name, resolved
  Location location;
};

// A block of the flattened model.
struct Node {
  std::string path;
  const Block* block = nullptr;
  std::string interrupt;  // the interrupt task it runs in, if inside a triggered subsystem
  std::vector<Input> inputs;
  std::vector<std::string> outputs;
  Rate rate;
  std::vector<std::string> enables;  // boolean signals of enclosing enabled subsystems: it runs while all are true
};

class FlatModel {
 public:
  explicit FlatModel(const Model& model) {
    scope(model.blocks, "", "", {});
    for (Node& node : nodes) {
      for (std::string& output : node.outputs) output = resolve(output);
      for (Input& input : node.inputs) input.signal = resolve(input.signal);
      for (std::string& enable : node.enables) enable = resolve(enable);
    }
  }

  std::vector<Node> nodes;
  // Blocks the flattening adds (edge detectors of triggered subsystems), kept while a node or a Program needs them.
  std::shared_ptr<std::deque<Block>> implied_blocks = std::make_shared<std::deque<Block>>();

  // Whether the model spells the node out (or the flattening implied it).
  [[nodiscard]] bool is_implied(const Node& node) const {
    return std::any_of(implied_blocks->begin(), implied_blocks->end(),
                       [&node](const Block& block) { return &block == node.block; });
  }

  // The signal a scope's name stands for: a subsystem's port name inside it is the parent's signal it is connected
  // to, and a parent's signal driven by a subsystem's output is the signal inside that drives it.
  [[nodiscard]] std::string resolve(std::string signal) const {
    for (std::size_t step = 0; step < aliases_.size() + 1; ++step) {  // bounded: aliases cannot cycle forever
      const auto found = aliases_.find(signal);
      if (found == aliases_.end()) return signal;
      signal = found->second;
    }
    return signal;
  }
  // The name a resolved signal has furthest out: a subsystem's output is known by the parent's signal it drives.
  [[nodiscard]] std::string outermost_name(const std::string& resolved) const {
    std::string best = resolved;
    for (const auto& [outer, inner] : aliases_) {
      if (resolve(outer) == resolved &&
          std::count(outer.begin(), outer.end(), '/') < std::count(best.begin(), best.end(), '/')) {
        best = outer;
      }
    }
    return best;
  }

 private:
  // Member by member: GCC 12 at -O3 takes a braced Node with an empty Rate for one read before it is written.
  static Node make_node(std::string path, const Block& block, std::string interrupt, std::vector<std::string> enables) {
    Node node;
    node.path = std::move(path);
    node.block = &block;
    node.interrupt = std::move(interrupt);
    node.enables = std::move(enables);
    return node;
  }

  static Block edge_detector(const Block& subsystem) {
    Block detector;
    detector.name = "trigger_edge";
    detector.type = "EdgeDetect";
    detector.location = subsystem.trigger.location;
    detector.type_location = subsystem.trigger.location;
    BlockParameter edge;
    edge.text = subsystem.trigger.edge;
    edge.location = subsystem.trigger.location;
    detector.parameters.emplace_back("edge", edge);
    detector.inputs.push_back({"u", subsystem.trigger.signal, subsystem.trigger.location, std::nullopt, {}});
    detector.outputs.push_back({"y", "triggered", subsystem.trigger.location, std::nullopt, {}});
    return detector;
  }

  void scope(const std::vector<Block>& blocks, const std::string& prefix, const std::string& interrupt,
             const std::vector<std::string>& enables) {
    for (const Block& block : blocks) {
      const std::string path = prefix + block.name;
      if (block.type == "Subsystem") {
        const std::string inner = path + "/";
        const std::string task = block.trigger.kind == Trigger::Kind::interrupt ? block.trigger.interrupt : interrupt;
        for (const Connection& input : block.inputs) aliases_[inner + input.port] = prefix + input.signal;
        for (const Connection& output : block.outputs) aliases_[prefix + output.signal] = inner + output.port;
        std::vector<std::string> inner_enables = enables;
        if (!block.enable.empty()) inner_enables.push_back(prefix + block.enable);
        if (block.trigger.kind == Trigger::Kind::edge) {
          // The edge is detected once per step of the triggering signal's rate, before the subsystem's blocks run.
          const Block& detector = implied_blocks->emplace_back(edge_detector(block));
          Node node = make_node(inner + detector.name, detector, interrupt, enables);
          node.inputs.push_back({prefix + block.trigger.signal, block.trigger.location});
          node.outputs.push_back(inner + detector.outputs[0].signal);
          nodes.push_back(std::move(node));
          inner_enables.push_back(inner + detector.outputs[0].signal);
        }
        scope(block.blocks, inner, task, inner_enables);
        continue;
      }
      Node node = make_node(path, block, interrupt, enables);
      for (const Connection& input : block.inputs) node.inputs.push_back({prefix + input.signal, input.location});
      for (const Connection& output : block.outputs) node.outputs.push_back(prefix + output.signal);
      nodes.push_back(std::move(node));
    }
  }

  std::map<std::string, std::string> aliases_;  // a subsystem's port signal -> the signal it stands for
};

}  // namespace duet::model
