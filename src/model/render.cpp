#include "duet/model/render.hpp"

#include <map>
#include <sstream>

#include "flat_model.hpp"

namespace duet::model {
namespace {

// Text inside a record label: Graphviz gives |{}<> and quotes a meaning there.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|' || c == '{' || c == '}' || c == '<' || c == '>' || c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

std::string ports(const std::vector<Connection>& connections) {
  std::string text;
  for (const Connection& connection : connections) {
    text += (text.empty() ? "" : "|") + std::string{"<"} + connection.port + "> " + connection.port;
  }
  return text;
}

void blocks(std::ostringstream& dot, const std::vector<Block>& list, const std::string& prefix, int depth) {
  const std::string indent(static_cast<std::size_t>(2 * depth), ' ');
  for (const Block& block : list) {
    const std::string path = prefix + block.name;
    if (block.type == "Subsystem") {
      std::string title = block.name;
      if (block.trigger.kind == Trigger::Kind::interrupt) {
        title += " (interrupt " + block.trigger.interrupt + ", priority " +
                 (block.trigger.priority ? std::to_string(*block.trigger.priority) : std::string{"auto"}) + ")";
      } else if (block.trigger.kind == Trigger::Kind::edge) {
        title += " (" + block.trigger.edge + " edge of " + block.trigger.signal + ")";
      }
      if (!block.enable.empty()) title += " (enabled by " + block.enable + ")";
      dot << indent << "subgraph \"cluster_" << path << "\" {\n"
          << indent << "  label=\"" << escaped(title) << "\"; style=rounded;\n";
      blocks(dot, block.blocks, path + "/", depth + 1);
      dot << indent << "}\n";
      continue;
    }
    const std::string in = ports(block.inputs);
    const std::string out = ports(block.outputs);
    dot << indent << "\"" << path << "\" [label=\"{" << (in.empty() ? "" : "{" + in + "}|") << escaped(block.name)
        << "\\n"
        << escaped(block.type) << (out.empty() ? "" : "|{" + out + "}") << "}\"];\n";
  }
}

}  // namespace

std::string to_dot(const Model& model) {
  std::ostringstream dot;
  dot << "digraph \"" << model.name << "\" {\n"
      << "  rankdir=LR; fontname=\"sans-serif\"; node [shape=record, fontname=\"sans-serif\", fontsize=10];\n"
      << "  edge [fontname=\"sans-serif\", fontsize=9];\n";
  blocks(dot, model.blocks, "", 1);
  // Connections between the blocks themselves, across subsystem borders.
  const FlatModel flat{model};
  std::map<std::string, std::pair<std::string, std::string>> driver_of;  // signal -> (block path, port)
  for (const Node& node : flat.nodes) {
    for (std::size_t k = 0; k < node.outputs.size(); ++k) {
      driver_of[node.outputs[k]] = {node.path, node.block->outputs[k].port};
    }
  }
  for (const Node& node : flat.nodes) {
    if (flat.is_implied(node)) continue;  // the trigger is drawn on the subsystem's frame
    for (std::size_t k = 0; k < node.inputs.size(); ++k) {
      const auto driver = driver_of.find(node.inputs[k].signal);
      if (driver == driver_of.end()) continue;
      const std::string signal = node.inputs[k].signal.substr(node.inputs[k].signal.rfind('/') + 1);
      dot << "  \"" << driver->second.first << "\":\"" << driver->second.second << "\" -> \"" << node.path << "\":\""
          << node.block->inputs[k].port << "\" [label=\"" << signal << "\"];\n";
    }
  }
  dot << "}\n";
  return dot.str();
}

}  // namespace duet::model
