#include "mdl_system.hpp"

#include <charconv>
#include <map>
#include <optional>
#include <utility>

namespace duet::simulink_import {
namespace {

// A block's name in a path: Simulink doubles a '/' inside a name; a newline reads better as a space in messages.
std::string path_of(const std::string& system_path, const std::string& block_name) {
  std::string path = system_path + "/";
  for (const char c : block_name) {
    if (c == '/')
      path += "//";
    else
      path += c == '\n' ? ' ' : c;
  }
  return path;
}

std::optional<int> positive_number(const std::string& text) {
  int number = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc{} || end != text.data() + text.size() || number < 1) return std::nullopt;
  return number;
}

Status add_mask_parameter(const MdlNode& object, Block& block, const std::string& file) {
  const MdlNode* name = find_pair(object, "Name");
  if (!name || name->value.empty())
    return mdl_failure(file, object.line, "mask parameter of block '" + block.name + "' without a Name");
  if (!block.mask_parameters.emplace(name->value, pair_value(object, "Value")).second)
    return mdl_failure(file, object.line, "mask parameter '" + name->value + "' given twice");
  return done();
}

// `Object { $PropName "MaskObject" ... }`: its parameters are `Object { $PropName "Parameters" ... }` sections, or
// the `Object`s of an `Array { PropName "Parameters" ... }` when there are several.
Status read_mask(const MdlNode& mask, Block& block, const std::string& file) {
  for (const MdlNode& child : mask.children) {
    if (!child.is_section) continue;
    const bool one_parameter = child.name == "Object" && pair_value(child, "$PropName") == "Parameters";
    const bool parameter_array = child.name == "Array" && pair_value(child, "PropName") == "Parameters";
    if (one_parameter) {
      Status added = add_mask_parameter(child, block, file);
      if (!added) return added;
    }
    if (!parameter_array) continue;
    for (const MdlNode& element : child.children) {
      if (!element.is_section || element.name != "Object") continue;
      Status added = add_mask_parameter(element, block, file);
      if (!added) return added;
    }
  }
  return done();
}

// `Port { PortNumber 2 Name "speed" }`: the name of the signal on an output port.
Status read_port(const MdlNode& port, Block& block, const std::string& file) {
  const MdlNode* name = find_pair(port, "Name");
  if (!name) return done();
  const MdlNode* number = find_pair(port, "PortNumber");
  const std::optional<int> index = number ? positive_number(number->value) : 1;
  if (!index) return mdl_failure(file, number->line, "PortNumber '" + number->value + "' is not a port number");
  block.output_names[*index] = name->value;
  return done();
}

Result<Block> read_block(const MdlNode& section, const std::string& system_path, const std::string& file) {
  Block block;
  block.line = section.line;
  block.type = pair_value(section, "BlockType");
  block.name = pair_value(section, "Name");
  block.sid = pair_value(section, "SID");
  if (block.name.empty())
    return mdl_failure(file, section.line, (block.type.empty() ? "block" : block.type + " block") + " without a Name");
  if (block.type.empty()) return mdl_failure(file, section.line, "block '" + block.name + "' without a BlockType");
  Status pairs = add_mdl_pairs(section, block.parameters, file, {"BlockType", "Name", "SID"});
  if (!pairs) return Failure{pairs.error()};
  for (const MdlNode& child : section.children) {
    if (!child.is_section) continue;
    Status read = done();
    if (child.name == "System") {
      if (!block.systems.empty())
        return mdl_failure(file, child.line, "block '" + block.name + "' has a second System");
      Result<System> system = read_mdl_system(child, path_of(system_path, block.name), file);
      if (!system) return Failure{system.error()};
      block.systems.push_back(std::move(system).value());
    } else if (child.name == "Object" && pair_value(child, "$PropName") == "MaskObject") {
      read = read_mask(child, block, file);
    } else if (child.name == "InstanceData") {
      read = add_mdl_pairs(child, block.mask_parameters, file);
    } else if (child.name == "Port") {
      read = read_port(child, block, file);
    }
    if (!read) return Failure{read.error()};
  }
  return block;
}

// A port as a line names it: a number, or the word of a special port.
std::optional<Endpoint> endpoint(const std::string& block, const std::string& port, const std::string& numbered_kind) {
  if (const std::optional<int> number = positive_number(port)) return Endpoint{block, numbered_kind, *number};
  for (const std::string_view word : {"trigger", "enable", "ifaction", "Reset", "state"})
    if (port == word) return Endpoint{block, port, 1};
  for (const auto& [prefix, kind] : {std::pair{"LConn", "lconn"}, std::pair{"RConn", "rconn"}}) {
    const std::string_view text{port};
    if (!text.starts_with(prefix)) continue;
    if (const std::optional<int> number = positive_number(port.substr(std::string_view{prefix}.size())))
      return Endpoint{block, kind, *number};
  }
  return std::nullopt;
}

class LineReader {
 public:
  LineReader(const std::map<std::string, int>& blocks, const std::string& system_path, const std::string& file)
      : blocks_{blocks}, system_path_{system_path}, file_{file} {}

  Result<Line> read(const MdlNode& section) {
    Line line;
    line.name = pair_value(section, "Name");
    Result<std::optional<Endpoint>> source = read_end(section, "Src", "out", "from");
    if (!source) return Failure{source.error()};
    line.source = std::move(source).value();
    Status destinations = add_destinations(section, line);
    if (!destinations) return Failure{destinations.error()};
    return line;
  }

 private:
  // A branch's destinations, and those of the branches it splits into (the parser bounds their nesting).
  Status add_destinations(const MdlNode& section, Line& line) {
    Result<std::optional<Endpoint>> destination = read_end(section, "Dst", "in", "to");
    if (!destination) return Failure{destination.error()};
    if (destination.value()) line.destinations.push_back(*destination.value());
    for (const MdlNode& child : section.children) {
      if (!child.is_section || child.name != "Branch") continue;
      Status added = add_destinations(child, line);
      if (!added) return added;
    }
    return done();
  }

  // `SrcBlock`/`SrcPort` or `DstBlock`/`DstPort`; none when the line is unconnected at that end.
  Result<std::optional<Endpoint>> read_end(const MdlNode& section, const std::string& side,
                                           const std::string& numbered_kind, const std::string& direction) {
    const MdlNode* block = find_pair(section, side + "Block");
    if (!block || block->value.empty()) return std::optional<Endpoint>{};
    if (!blocks_.contains(block->value))
      return mdl_failure(
          file_, block->line,
          "line " + direction + " '" + block->value + "', which system '" + system_path_ + "' does not have");
    const MdlNode* port = find_pair(section, side + "Port");
    if (!port)
      return mdl_failure(file_, block->line, "line " + direction + " '" + block->value + "' without " + side + "Port");
    std::optional<Endpoint> end = endpoint(block->value, port->value, numbered_kind);
    if (!end)
      return mdl_failure(file_, port->line,
                         side + "Port '" + port->value +
                             "' is not a port: a number, trigger, enable, ifaction, Reset, state, "
                             "LConn<n> or RConn<n>");
    return end;
  }

  const std::map<std::string, int>& blocks_;
  const std::string& system_path_;
  const std::string& file_;
};

}  // namespace

Result<System> read_mdl_system(const MdlNode& section, const std::string& path, const std::string& file) {
  System system;
  system.part = file;
  std::map<std::string, int> lines_of_blocks;
  for (const MdlNode& child : section.children) {
    if (!child.is_section || child.name != "Block") continue;
    Result<Block> block = read_block(child, path, file);
    if (!block) return Failure{block.error()};
    const auto [other, added] = lines_of_blocks.emplace(block.value().name, child.line);
    if (!added)
      return mdl_failure(file, child.line,
                         "two blocks named '" + block.value().name + "' in system '" + path + "' (the other on line " +
                             std::to_string(other->second) + ")");
    system.blocks.push_back(std::move(block).value());
  }
  LineReader lines{lines_of_blocks, path, file};
  for (const MdlNode& child : section.children) {
    if (!child.is_section || child.name != "Line") continue;
    Result<Line> line = lines.read(child);
    if (!line) return Failure{line.error()};
    system.lines.push_back(std::move(line).value());
  }
  return system;
}

}  // namespace duet::simulink_import
