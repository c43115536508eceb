#include "duet_text.hpp"

#include <algorithm>
#include <cmath>

#include "duet/support/number_text.hpp"

namespace duet::simulink_import {
namespace {

std::string pairs(const TextPairs& items) {
  std::string text = "{";
  for (const auto& [name, value] : items) text += (text.size() > 1 ? ", " : "") + name + ": " + value;
  return text + "}";
}

// Comments are one line: a newline in a Simulink name would end the comment.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

void write_block(const DuetBlock& block, const std::string& indent, std::string& text) {
  text += indent + "# " + one_line(block.source) + "\n";
  text += indent + "- name: " + block.name + "\n";
  const std::string inner = indent + "  ";
  text += inner + "type: " + block.type + "\n";
  if (!block.period.empty()) text += inner + block.period + "\n";
  if (!block.trigger.empty()) text += inner + "trigger: " + block.trigger + "\n";
  if (!block.enable.empty()) text += inner + "enable: " + block.enable + "\n";
  if (!block.parameters.empty()) text += inner + "parameters: " + pairs(block.parameters) + "\n";
  if (!block.inputs.empty()) text += inner + "inputs: " + pairs(block.inputs) + "\n";
  if (!block.outputs.empty()) text += inner + "outputs: " + pairs(block.outputs) + "\n";
  if (block.type == "Subsystem") {
    // A subsystem whose blocks all come to nothing (a Terminator alone) is still one: an empty list.
    text += inner + (block.blocks.empty() ? "blocks: []\n" : "blocks:\n");
    for (const DuetBlock& child : block.blocks) write_block(child, inner + "  ", text);
  }
}

}  // namespace

std::string yaml_number(double value) {
  if (std::isinf(value)) return value > 0 ? ".inf" : "-.inf";
  if (std::isnan(value)) return ".nan";
  return shortest_text(value);
}

std::string yaml_value(const Value& value) {
  const auto row = [&value](std::size_t r) {
    std::string text = "[";
    for (std::size_t c = 0; c < value.columns; ++c) text += (c == 0 ? "" : ", ") + yaml_number(value.at(r, c));
    return text + "]";
  };
  if (value.is_scalar()) return yaml_number(value.elements.front());
  if (value.rows == 1) return row(0);
  std::string text = "[";
  for (std::size_t r = 0; r < value.rows; ++r)
    text += (r == 0 ? "" : ", ") + (value.columns == 1 ? yaml_number(value.at(r, 0)) : row(r));
  return text + "]";
}

std::string yaml_string(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
  const bool reads_as_other = text == "true" || text == "false" || text == "null" || text == "yes" || text == "no" ||
                              text == "on" || text == "off" || (!text.empty() && text[0] >= '0' && text[0] <= '9');
  if (plain && !reads_as_other) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    if (c == '\n') {
      quoted += "\\n";
      continue;
    }
    quoted += c;
  }
  return quoted + "\"";
}

std::string duet_model_text(const DuetModel& model) {
  std::string text = "duet_model: 1\nname: " + model.name + "\n";
  text += "description: " + yaml_string(model.description) + "\n";
  text += "base_period_us: " + std::to_string(model.base_period_us) + "\n";
  if (!model.parameters.empty()) {
    text += "parameters:\n";
    for (const DuetParameter& parameter : model.parameters) {
      text += "  " + parameter.name + ": {value: " + parameter.value +
              (parameter.type.empty() ? "" : ", type: " + parameter.type) +
              ", description: " + yaml_string(one_line(parameter.source)) + "}\n";
    }
  }
  text += "blocks:\n";
  for (const DuetBlock& block : model.blocks) write_block(block, "  ", text);
  return text;
}

}  // namespace duet::simulink_import
