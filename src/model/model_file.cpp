#include "duet/model/model_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "duet/model/block_types.hpp"
#include "duet/model/data_type.hpp"
#include "duet/support/number_text.hpp"
#include "duet/support/text_file.hpp"
#include "model_reference.hpp"

namespace duet::model {
namespace {

// The first problem found; caught once, at the top.
struct Problem {
  Diagnostic diagnostic;
};

Location location_of(const YAML::Node& node) { return {node.Mark().line + 1, node.Mark().column + 1}; }

[[noreturn]] void fail(const YAML::Node& node, const std::string& message, const std::string& hint = {}) {
  throw Problem{{Diagnostic::Severity::error, location_of(node), message, hint}};
}

bool is_identifier(const std::string& text) {
  if (text.empty() || !(std::isalpha(static_cast<unsigned char>(text[0])) != 0 || text[0] == '_')) return false;
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; });
}

std::string identifier(const YAML::Node& node, const std::string& what) {
  if (!node.IsScalar()) fail(node, what + " must be a name");
  const std::string text = node.Scalar();
  if (!is_identifier(text)) {
    fail(node, what + " '" + text + "' is not a name", "letters, digits and _, not starting with a digit");
  }
  return text;
}

void only(const YAML::Node& map, const std::string& where, std::initializer_list<const char*> known) {
  for (const auto& entry : map) {
    const std::string key = entry.first.Scalar();
    if (std::none_of(known.begin(), known.end(), [&key](const char* name) { return key == name; })) {
      std::string list;
      for (const char* name : known) list += (list.empty() ? "" : ", ") + std::string{name};
      fail(entry.first, "unknown field '" + key + "' in " + where, "known: " + list);
    }
  }
}

// `labels: [initialising, balancing, stopped]`: value k is named labels[k], so that tools show the name (an A2L
// verbal conversion). Only booleans (false's name, then true's) and integers name their values.
std::vector<std::string> labels(const YAML::Node& node, std::optional<DataType> type, const std::string& what) {
  if (!node.IsSequence() || node.size() < 2) fail(node, what + ": labels is a list of at least two names");
  if (!type || !(*type == DataType::boolean || is_integer(*type))) {
    fail(node, what + ": only a boolean or an integer type names its values", "declare its type");
  }
  if (*type == DataType::boolean && node.size() != 2)
    fail(node, what + ": a boolean has two labels, false's and true's");
  if (!fits(static_cast<double>(node.size() - 1), *type)) {
    fail(node, what + ": more labels than values of its type " + std::string{type_name(*type)});
  }
  std::vector<std::string> names;
  for (const YAML::Node& label : node) {
    const std::string name = label.IsScalar() ? label.Scalar() : std::string{};
    if (name.empty() || name.find('"') != std::string::npos) fail(label, what + ": a label is a name without quotes");
    if (std::find(names.begin(), names.end(), name) != names.end()) fail(label, what + ": '" + name + "' twice");
    names.push_back(name);
  }
  return names;
}

YAML::Node map_of(const YAML::Node& node, const std::string& what) {
  if (!node.IsMap()) fail(node, what + " must be a map of fields");
  return node;
}

double number(const YAML::Node& node, const std::string& what) {
  double value = 0;
  if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
    bool flag = false;
    if (node.IsScalar() && YAML::convert<bool>::decode(node, flag)) return flag ? 1.0 : 0.0;
    fail(node, what + " must be a number", node.IsScalar() ? "got '" + node.Scalar() + "'" : "");
  }
  return value;
}

// A scalar, a list (vector) or a list of equally long lists (matrix) of numbers or booleans.
Value literal(const YAML::Node& node, const std::string& what) {
  Value value;
  if (node.IsScalar()) {
    value.elements.push_back(number(node, what));
    return value;
  }
  if (!node.IsSequence() || node.size() == 0) fail(node, what + " must be a number, a list or a list of rows");
  if (node[0].IsSequence()) {
    const std::size_t columns = node[0].size();
    for (const auto& row : node) {
      if (!row.IsSequence() || row.size() != columns) {
        fail(row, what + ": every row of a matrix needs " + std::to_string(columns) + " elements");
      }
      for (const auto& element : row) value.elements.push_back(number(element, what));
    }
    value.shape = {node.size(), columns};
    return value;
  }
  for (const auto& element : node) value.elements.push_back(number(element, what));
  value.shape = {node.size()};
  return value;
}

DataType data_type(const YAML::Node& node) {
  const auto found = node.IsScalar() ? parse_type_name(node.Scalar()) : std::nullopt;
  if (!found) {
    fail(node, "unknown data type '" + (node.IsScalar() ? node.Scalar() : std::string{"?"}) + "'",
         "double, single, int8, int16, int32, uint8, uint16, uint32 or boolean");
  }
  return *found;
}

// A value of the given size: a scalar fills it (a table of 4096 zeros is `value: 0, size: 4096`); a list must have it.
Value sized(const Value& value, const std::vector<std::size_t>& size, const YAML::Node& where) {
  std::size_t count = 1;
  for (const std::size_t dimension : size) count *= dimension;
  if (value.shape.empty()) return {std::vector<double>(count, value.elements.front()), size};
  if (value.shape != size) fail(where, "the size does not match the value's", "give a single value to fill it");
  return value;
}

std::vector<std::size_t> shape(const YAML::Node& node) {
  std::vector<std::size_t> result;
  const auto dimension = [](const YAML::Node& n) {
    int size = 0;
    if (!n.IsScalar() || !YAML::convert<int>::decode(n, size) || size < 1)
      fail(n, "a size must be a whole number >= 1");
    return static_cast<std::size_t>(size);
  };
  if (node.IsSequence()) {
    if (node.size() < 1 || node.size() > 2) fail(node, "size: one number (vector) or two (matrix)");
    for (const auto& n : node) result.push_back(dimension(n));
  } else {
    result.push_back(dimension(node));
  }
  // Far more than a real-time core holds; and a size a typo made huge must not exhaust the PC's memory either.
  constexpr std::size_t most_elements = 1'000'000;
  std::size_t elements = 1;
  for (const std::size_t size : result) elements *= size;
  if (elements > most_elements) {
    fail(node, "a size of " + std::to_string(elements) + " elements is more than " + std::to_string(most_elements),
         "a real-time core holds far less");
  }
  return result;
}

// A number as a person writes it: 100, 0.5.
std::string shortest(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

Period period(const YAML::Node& block, double base_period_us) {
  Period result;
  if (block["period"] && block["period_us"]) fail(block["period_us"], "give 'period' or 'period_us', not both");
  if (const YAML::Node node = block["period"]) {
    result.location = location_of(node);
    if (node.IsScalar() && node.Scalar() == "base") {
      result.kind = Period::Kind::base;
    } else if (node.IsScalar() && node.Scalar() == "inherited") {
      result.kind = Period::Kind::inherited;
    } else if (node.IsScalar() && node.Scalar() == "constant") {
      result.kind = Period::Kind::constant;
    } else if (node.IsMap() && node["multiple"]) {
      only(node, "period", {"multiple"});
      int multiple = 0;
      if (!YAML::convert<int>::decode(node["multiple"], multiple) || multiple < 1) {
        fail(node["multiple"], "period: multiple must be a whole number >= 1");
      }
      result.kind = Period::Kind::multiple;
      result.multiple = multiple;
    } else {
      fail(node, "period must be base, inherited, constant or {multiple: N}", "or give period_us");
    }
  } else if (const YAML::Node us = block["period_us"]) {
    result.location = location_of(us);
    const double value = number(us, "period_us");
    const double multiple = value / base_period_us;
    if (value <= 0 || std::fabs(multiple - std::round(multiple)) > 1e-9 * multiple) {
      fail(us, "period_us " + us.Scalar() + " is not a whole multiple of the base period",
           "base_period_us is " + shortest(base_period_us));
    }
    result.kind = std::llround(multiple) == 1 ? Period::Kind::base : Period::Kind::multiple;
    result.multiple = std::llround(multiple);
  }
  return result;
}

// Port: signal, or for a Code block port: {signal: NAME, type: TYPE, size: N}.
std::vector<Connection> connections(const YAML::Node& node, const std::string& what, bool typed) {
  std::vector<Connection> result;
  if (!node) return result;
  map_of(node, what);
  for (const auto& entry : node) {
    Connection connection{identifier(entry.first, "a port"), {}, location_of(entry.first), std::nullopt, {}};
    if (!typed) {
      connection.signal = identifier(entry.second, "a signal");
    } else {
      if (!entry.second.IsMap()) {
        fail(entry.second, "a Code block's port names its signal and its type", "{signal: NAME, type: TYPE}");
      }
      only(entry.second, "port " + connection.port, {"signal", "type", "size"});
      if (!entry.second["signal"]) fail(entry.second, "port " + connection.port + " needs 'signal'");
      if (!entry.second["type"]) fail(entry.second, "port " + connection.port + " needs 'type'");
      connection.signal = identifier(entry.second["signal"], "a signal");
      connection.type = data_type(entry.second["type"]);
      if (entry.second["size"]) connection.shape = shape(entry.second["size"]);
    }
    result.push_back(std::move(connection));
  }
  return result;
}

UserCode user_code(const YAML::Node& node, const std::string& name) {
  UserCode code;
  if (!node["function"]) fail(node, "Code block '" + name + "' needs 'function'", "the C++ function it calls");
  code.function = identifier(node["function"], "a function");
  if (!node["file"] || !node["file"].IsScalar() || node["file"].Scalar().empty()) {
    fail(node, "Code block '" + name + "' needs 'file'", "the header that declares the function, beside the model");
  }
  code.file = node["file"].Scalar();
  code.file_location = location_of(node["file"]);
  if (const YAML::Node feedthrough = node["direct_feedthrough"]) {
    if (!YAML::convert<bool>::decode(feedthrough, code.direct_feedthrough)) {
      fail(feedthrough, "direct_feedthrough is true or false");
    }
  }
  if (const YAML::Node state = node["state"]) {
    map_of(state, "state");
    for (const auto& entry : state) {
      StateVariable variable;
      variable.name = identifier(entry.first, "a state variable");
      variable.location = location_of(entry.first);
      map_of(entry.second, "state " + variable.name);
      only(entry.second, "state " + variable.name, {"type", "size", "initial"});
      if (!entry.second["type"]) fail(entry.second, "state " + variable.name + " needs 'type'");
      variable.type = data_type(entry.second["type"]);
      if (entry.second["size"]) variable.shape = shape(entry.second["size"]);
      variable.initial =
          entry.second["initial"] ? literal(entry.second["initial"], "state " + variable.name) : Value{{0.0}, {}};
      code.state.push_back(std::move(variable));
    }
  }
  return code;
}

Trigger trigger(const YAML::Node& node) {
  Trigger result;
  result.location = location_of(node);
  map_of(node, "trigger");
  if (node["interrupt"]) {
    only(node, "trigger", {"interrupt", "priority"});
    result.kind = Trigger::Kind::interrupt;
    result.interrupt = identifier(node["interrupt"], "an interrupt");
    if (const YAML::Node priority = node["priority"];
        priority && !(priority.IsScalar() && priority.Scalar() == "auto")) {
      int value = 0;
      if (!YAML::convert<int>::decode(priority, value) || value < 0 || value > 255) {
        fail(priority, "priority must be a whole number 0..255 or auto");
      }
      result.priority = value;
    }
  } else if (node["edge"]) {
    only(node, "trigger", {"edge", "signal"});
    result.kind = Trigger::Kind::edge;
    result.edge = node["edge"].Scalar();
    if (result.edge != "rising" && result.edge != "falling" && result.edge != "either") {
      fail(node["edge"], "edge must be rising, falling or either");
    }
    if (!node["signal"]) fail(node, "an edge trigger needs 'signal'");
    result.signal = identifier(node["signal"], "a signal");
  } else {
    fail(node, "a trigger is {interrupt: NAME, priority: P} or {edge: rising|falling|either, signal: NAME}");
  }
  return result;
}

// A whole number in [low, high].
std::uint32_t whole_number(const YAML::Node& node, const std::string& what, std::uint32_t low, std::uint32_t high) {
  const double value = number(node, what);
  if (value != std::floor(value) || value < low || value > high) {
    fail(node, what + " must be a whole number " + std::to_string(low) + ".." + std::to_string(high));
  }
  return static_cast<std::uint32_t>(value);
}

XcpSettings xcp_settings(const YAML::Node& node) {
  map_of(node, "xcp");
  only(node, "xcp",
       {"max_cto", "max_dto", "daq_lists", "odts", "odt_entries", "queue_bytes", "download_bytes", "identification",
        "timestamp_bytes"});
  XcpSettings xcp;
  xcp.location = location_of(node);
  // XCP's own limits: a CTO length is a byte, a DTO length a word; DAQ list numbers are words, and a packet's
  // identification byte stays below the response codes (0xFC and up), so a list has at most 252 ODTs.
  if (node["max_cto"]) xcp.max_cto = whole_number(node["max_cto"], "max_cto", 8, 255);
  if (node["max_dto"]) xcp.max_dto = whole_number(node["max_dto"], "max_dto", 8, 65535);
  if (node["daq_lists"]) xcp.daq_lists = whole_number(node["daq_lists"], "daq_lists", 1, 65535);
  if (node["odts"]) xcp.odts = whole_number(node["odts"], "odts", 1, 65535);
  if (node["odt_entries"]) xcp.odt_entries = whole_number(node["odt_entries"], "odt_entries", 1, 65535);
  if (node["queue_bytes"]) xcp.queue_bytes = whole_number(node["queue_bytes"], "queue_bytes", 64, 1U << 24U);
  if (node["download_bytes"]) xcp.download_bytes = whole_number(node["download_bytes"], "download_bytes", 8, 65535);
  if (const YAML::Node identification = node["identification"]) {
    constexpr std::array<std::string_view, 4> kinds{"absolute", "relative_byte", "relative_word",
                                                    "relative_word_aligned"};
    xcp.identification = identification.IsScalar() ? identification.Scalar() : "";
    if (std::find(kinds.begin(), kinds.end(), xcp.identification) == kinds.end()) {
      fail(identification, "identification must be absolute, relative_byte, relative_word or relative_word_aligned");
    }
  }
  if (const YAML::Node timestamp = node["timestamp_bytes"]) {
    xcp.timestamp_bytes = whole_number(timestamp, "timestamp_bytes", 1, 4);
    if (xcp.timestamp_bytes == 3) fail(timestamp, "timestamp_bytes must be 1, 2 or 4");
  }
  // What a table or a packet must hold at least, so that a master can use what the A2L promises.
  if (xcp.identification == "absolute" && xcp.odts > 252) {
    fail(node["odts"], "odts must be at most 252 with absolute identification",
         "an absolute ODT number is one byte below 0xFC; relative identification numbers ODTs per list");
  }
  if (xcp.identification == "relative_byte" && xcp.daq_lists > 256) {
    fail(node["daq_lists"], "daq_lists must be at most 256 with relative_byte identification");
  }
  if (xcp.download_bytes < xcp.max_cto - 2) {
    fail(node["download_bytes"] ? node["download_bytes"] : node,
         "download_bytes must hold one DOWNLOAD's data: at least max_cto - 2 = " + std::to_string(xcp.max_cto - 2));
  }
  const std::uint32_t largest_packet = std::max(xcp.max_cto, xcp.max_dto) + 2;  // with the queue's record header
  if (xcp.queue_bytes < 2 * largest_packet) {
    fail(node["queue_bytes"] ? node["queue_bytes"] : node,
         "queue_bytes must hold a DAQ packet and a response: at least " + std::to_string(2 * largest_packet));
  }
  return xcp;
}

Block block(const YAML::Node& node, double base_period_us) {
  map_of(node, "a block");
  Block result;
  result.location = location_of(node);
  if (!node["name"]) fail(node, "a block needs 'name'");
  result.name = identifier(node["name"], "a block name");
  if (!node["type"]) fail(node, "block '" + result.name + "' needs 'type'");
  if (!node["type"].IsScalar()) fail(node["type"], "a block type must be a name");
  result.type = node["type"].Scalar();
  result.type_location = location_of(node["type"]);
  const bool is_code = result.type == "Code";
  only(node, "block '" + result.name + "'",
       {"name", "type", "period", "period_us", "parameters", "inputs", "outputs", "blocks", "trigger", "enable",
        "description", "function", "file", "state", "direct_feedthrough", "model"});
  if (!is_code) {
    for (const char* field : {"function", "file", "state", "direct_feedthrough"}) {
      if (node[field])
        fail(node[field], "'" + std::string{field} + "' belongs to Code blocks",
             "block '" + result.name + "' is a " + result.type);
    }
  } else {
    result.code = user_code(node, result.name);
  }
  result.period = period(node, base_period_us);
  if (const YAML::Node parameters = node["parameters"]) {
    map_of(parameters, "parameters");
    for (const auto& entry : parameters) {
      BlockParameter parameter;
      parameter.location = location_of(entry.second);
      const std::string name = identifier(entry.first, "a parameter");
      if (is_code && entry.second.IsMap()) {  // {value: V, type: T}
        only(entry.second, "parameter " + name, {"value", "type"});
        if (!entry.second["value"]) fail(entry.second, "parameter " + name + " needs 'value'");
        parameter.literal = literal(entry.second["value"], "parameter " + name);
        parameter.text = entry.second["value"].IsScalar() ? entry.second["value"].Scalar() : "(list)";
        if (entry.second["type"]) parameter.type = data_type(entry.second["type"]);
      } else if (entry.second.IsScalar() && is_word_parameter(name)) {  // a pin, an operator, ...: kept as written
        parameter.text = entry.second.Scalar();
      } else if (entry.second.IsScalar() && is_identifier(entry.second.Scalar()) && entry.second.Scalar() != "true" &&
                 entry.second.Scalar() != "false") {
        parameter.reference = entry.second.Scalar();
        parameter.text = parameter.reference;
      } else {
        parameter.literal = literal(entry.second, "parameter " + name);
        parameter.text = entry.second.IsScalar() ? entry.second.Scalar() : "(list)";
      }
      result.parameters.emplace_back(name, parameter);
    }
  }
  result.inputs = connections(node["inputs"], "inputs", is_code);
  result.outputs = connections(node["outputs"], "outputs", is_code);
  if (const YAML::Node model = node["model"]) {
    if (result.type != "Subsystem") {
      fail(model, "'model' belongs to Subsystem blocks", "block '" + result.name + "' is a " + result.type);
    }
    if (!model.IsScalar() || model.Scalar().empty()) fail(model, "'model' is the referenced model's file");
    if (node["blocks"]) fail(node["blocks"], "a model reference takes its blocks from its file", "remove 'blocks'");
    result.model = model.Scalar();
    result.model_location = location_of(model);
  }
  if (const YAML::Node blocks = node["blocks"]) {
    if (!blocks.IsSequence()) fail(blocks, "blocks must be a list");
    for (const auto& inner : blocks) result.blocks.push_back(block(inner, base_period_us));
  }
  if (node["trigger"]) result.trigger = trigger(node["trigger"]);
  if (node["enable"]) result.enable = identifier(node["enable"], "an enabling signal");
  return result;
}

Model model(const YAML::Node& root, const std::string& file) {
  Model result;
  result.file = file;
  if (!root.IsMap()) fail(root, "a model file is a map of fields", "it starts with 'duet_model: 1'");
  if (!root["duet_model"]) fail(root, "'duet_model' is missing", "the first line of a model is 'duet_model: 1'");
  int version = 0;
  if (!YAML::convert<int>::decode(root["duet_model"], version) || version != format_version) {
    fail(root["duet_model"], "this is duet model format " + root["duet_model"].Scalar() + "; duet reads version " +
                                 std::to_string(format_version));
  }
  result.version = version;
  only(root, "the model",
       {"duet_model", "name", "description", "base_period_us", "precision", "constants", "parameters", "signals",
        "blocks", "xcp"});
  if (!root["name"]) fail(root, "'name' is missing");
  result.name = identifier(root["name"], "the model name");
  if (root["description"]) result.description = root["description"].Scalar();
  if (const YAML::Node precision = root["precision"]) {
    if (!precision.IsScalar() || (precision.Scalar() != "single" && precision.Scalar() != "double")) {
      fail(precision, "'precision' is single or double", "double: the model computes in double on purpose");
    }
    result.double_precision = precision.Scalar() == "double";
  }
  if (!root["base_period_us"]) fail(root, "'base_period_us' is missing", "the executive's tick, e.g. 100");
  result.base_period_location = location_of(root["base_period_us"]);
  result.base_period_us = number(root["base_period_us"], "base_period_us");
  if (result.base_period_us <= 0) fail(root["base_period_us"], "base_period_us must be more than 0");

  std::set<std::string> names;
  const auto unique = [&names](const YAML::Node& key, const std::string& name) {
    if (!names.insert(name).second)
      fail(key, "'" + name + "' is defined twice", "constants and parameters share names");
  };
  if (const YAML::Node constants = root["constants"]) {
    map_of(constants, "constants");
    for (const auto& entry : constants) {
      const std::string name = identifier(entry.first, "a constant");
      unique(entry.first, name);
      result.constants.push_back({name, literal(entry.second, "constant " + name), location_of(entry.first)});
    }
  }
  if (const YAML::Node parameters = root["parameters"]) {
    map_of(parameters, "parameters");
    for (const auto& entry : parameters) {
      Parameter parameter;
      parameter.name = identifier(entry.first, "a parameter");
      unique(entry.first, parameter.name);
      parameter.location = location_of(entry.first);
      const YAML::Node fields = entry.second.IsMap() ? entry.second : YAML::Node{};
      if (!entry.second.IsMap()) {
        parameter.value = literal(entry.second, "parameter " + parameter.name);
      } else {
        only(fields, "parameter " + parameter.name,
             {"value", "type", "size", "unit", "min", "max", "description", "labels"});
        if (!fields["value"]) fail(entry.second, "parameter " + parameter.name + " needs 'value'");
        parameter.value = literal(fields["value"], "parameter " + parameter.name);
        if (fields["type"]) parameter.type = data_type(fields["type"]);
        if (fields["size"]) parameter.value = sized(parameter.value, shape(fields["size"]), fields["size"]);
        if (fields["unit"]) parameter.unit = fields["unit"].Scalar();
        if (fields["min"]) parameter.minimum = number(fields["min"], "min");
        if (fields["max"]) parameter.maximum = number(fields["max"], "max");
        if (fields["description"]) parameter.description = fields["description"].Scalar();
        if (fields["labels"])
          parameter.labels = labels(fields["labels"], parameter.type, "parameter " + parameter.name);
        if (parameter.minimum && parameter.maximum && *parameter.minimum > *parameter.maximum) {
          fail(fields["min"], "parameter " + parameter.name + ": min is above max");
        }
        for (double element : parameter.value.elements) {
          if (!fits(element, parameter.type)) {
            fail(fields["value"], "parameter " + parameter.name + ": " + shortest_text(element) +
                                      " is not a value of " + "its type " + std::string{type_name(parameter.type)});
          }
          if ((parameter.minimum && element < *parameter.minimum) ||
              (parameter.maximum && element > *parameter.maximum)) {
            fail(fields["value"], "parameter " + parameter.name + ": the value is outside [min, max]");
          }
        }
      }
      result.parameters.push_back(parameter);
    }
  }
  if (const YAML::Node signals = root["signals"]) {
    map_of(signals, "signals");
    for (const auto& entry : signals) {
      SignalDeclaration signal;
      signal.name = identifier(entry.first, "a signal");
      signal.location = location_of(entry.first);
      map_of(entry.second, "signal " + signal.name);
      only(entry.second, "signal " + signal.name, {"type", "size", "unit", "measurable", "description", "labels"});
      if (entry.second["type"]) signal.type = data_type(entry.second["type"]);
      if (entry.second["size"]) signal.shape = shape(entry.second["size"]);
      if (entry.second["unit"]) signal.unit = entry.second["unit"].Scalar();
      if (entry.second["description"]) signal.description = entry.second["description"].Scalar();
      if (entry.second["labels"]) signal.labels = labels(entry.second["labels"], signal.type, "signal " + signal.name);
      if (const YAML::Node measurable = entry.second["measurable"]) {
        if (!YAML::convert<bool>::decode(measurable, signal.measurable))
          fail(measurable, "measurable is true or false");
      }
      result.signals.push_back(signal);
    }
  }
  if (const YAML::Node xcp = root["xcp"]) result.xcp = xcp_settings(xcp);
  const YAML::Node blocks = root["blocks"];
  if (!blocks || !blocks.IsSequence() || blocks.size() == 0) fail(root, "'blocks' is missing or empty");
  for (const auto& node : blocks) result.blocks.push_back(block(node, result.base_period_us));
  return result;
}

}  // namespace

Result<Model> parse_referenced_model(std::string_view text, const std::string& file,
                                     const std::vector<std::string>& chain) {
  Model read;
  try {
    const YAML::Node root = YAML::Load(std::string{text});
    read = model(root, file);
  } catch (const Problem& problem) {
    return Failure{format(file, problem.diagnostic)};
  } catch (const YAML::Exception& error) {
    return Failure{format(
        file,
        {Diagnostic::Severity::error, {error.mark.line + 1, error.mark.column + 1, {}}, "not YAML: " + error.msg, ""})};
  }
  if (auto expanded = expand_references(read, chain); !expanded) return Failure{expanded.error()};
  return read;
}

Result<Model> load_referenced_model(const std::string& path, const std::vector<std::string>& chain) {
  auto text = read_text_file(path);
  if (!text) return Failure{text.error()};
  return parse_referenced_model(text.value(), path, chain);
}

Result<Model> parse_model(std::string_view text, const std::string& file) {
  return parse_referenced_model(text, file, {});
}

Result<Model> load_model(const std::string& path) { return load_referenced_model(path, {}); }

}  // namespace duet::model
