#include "duet/studio/model_view.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <optional>

#include "duet/model/block_types.hpp"
#include "duet/model/data_type.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/signal_names.hpp"
#include "duet/model/task_set_file.hpp"
#include "duet/support/number_text.hpp"
#include "duet/support/text_file.hpp"

namespace duet::studio {
namespace {

using model::Block;
using model::Connection;
using model::Location;
using nlohmann::json;

// The reader stops at its first problem and says it as `file:line:column: error: what (hint)`; the file is another
// than `model_file` when the problem is in a referenced model.
model::Diagnostic parse_problem(const std::string& text, const std::string& model_file) {
  model::Diagnostic diagnostic;
  diagnostic.message = text;
  for (const char* marker : {": error: ", ": warning: "}) {
    const auto at = text.find(marker);
    if (at == std::string::npos) continue;
    const auto column_colon = text.rfind(':', at - 1);
    const auto line_colon = column_colon == std::string::npos ? std::string::npos : text.rfind(':', column_colon - 1);
    if (line_colon == std::string::npos) continue;
    int line = 0;
    int column = 0;
    const char* line_text = text.data() + line_colon + 1;
    const char* column_text = text.data() + column_colon + 1;
    if (std::from_chars(line_text, text.data() + column_colon, line).ec != std::errc{} ||
        std::from_chars(column_text, text.data() + at, column).ec != std::errc{}) {
      continue;
    }
    const std::string file = text.substr(0, line_colon);
    diagnostic.location = {line, column, file == model_file ? std::string{} : file};
    diagnostic.message = text.substr(at + std::string_view{marker}.size());
    break;
  }
  if (diagnostic.location.line == 0) diagnostic.location = {1, 1, {}};  // a problem of the whole file
  return diagnostic;
}

// Where a place is, for the page: its line and column, and the file when it is not the open model's (a referenced
// model's blocks, parameters and diagnostics), by its path from the model's folder as the page names files.
class Places {
 public:
  explicit Places(const std::string& model_file)
      : folder_(std::filesystem::path{model_file}.parent_path()),
        model_name_(std::filesystem::path{model_file}.filename().generic_string()) {}

  // Empty for the open model's own places.
  [[nodiscard]] std::string file_of(const Location& location) const {
    if (location.file.empty()) return {};
    const std::filesystem::path file{location.file};
    const std::filesystem::path relative = folder_.empty() ? file : file.lexically_relative(folder_);
    return (relative.empty() ? file : relative).generic_string();
  }

  // A diagnostic names its file always: the open model's is the name the page was given (`studio`'s `file`).
  [[nodiscard]] std::string diagnostic_file(const Location& location) const {
    return location.file.empty() ? model_name_ : file_of(location);
  }

  [[nodiscard]] json json_of(const Location& location) const {
    json place = {{"line", location.line}, {"column", location.column}};
    if (!location.file.empty()) place["file"] = file_of(location);
    return place;
  }

 private:
  std::filesystem::path folder_;
  std::string model_name_;
};

// How far each line of a text is indented, for the lines each block spans; blank and comment lines are none.
class Lines {
 public:
  explicit Lines(std::string_view text) {
    std::size_t start = 0;
    while (start <= text.size()) {
      const auto end = text.find('\n', start);
      const std::string_view line =
          text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
      const auto indentation = line.find_first_not_of(' ');
      const bool content = indentation != std::string_view::npos && line[indentation] != '#';
      indentations_.push_back(content ? std::optional<std::size_t>{indentation} : std::nullopt);
      if (end == std::string_view::npos) break;
      start = end + 1;
    }
  }

  // The last line of the block whose mapping starts at `start`: the following lines indented at least as far as its
  // keys belong to it; blank and comment lines only where more of it follows.
  [[nodiscard]] int block_end(Location start) const {
    int last = start.line;
    for (int line = start.line + 1; line <= static_cast<int>(indentations_.size()); ++line) {
      const auto indentation = indentations_[static_cast<std::size_t>(line - 1)];
      if (!indentation) continue;
      if (static_cast<int>(*indentation) < start.column - 1) break;
      last = line;
    }
    return last;
  }

 private:
  std::vector<std::optional<std::size_t>> indentations_;
};

// The lines of the open text, and of each referenced model's file, read when a block of it is first drawn.
class SourceLines {
 public:
  explicit SourceLines(std::string_view text) : own_(text) {}

  [[nodiscard]] int block_end(const Location& start) {
    if (start.file.empty()) return own_.block_end(start);
    auto found = referenced_.find(start.file);
    if (found == referenced_.end()) {
      const auto text = read_text_file(start.file);  // the reader has just read it; gone since, the block is one line
      found = referenced_.emplace(start.file, Lines{text ? std::string_view{text.value()} : std::string_view{}}).first;
    }
    return found->second.block_end(start);
  }

 private:
  Lines own_;
  std::map<std::string, Lines> referenced_;
};

std::string value_text(const model::Value& value) {
  auto element = [&](std::size_t index) { return shortest_text(value.elements[index]); };
  if (value.shape.empty() && value.elements.size() == 1) return element(0);
  std::string text = "[";
  if (value.shape.size() == 2) {
    for (std::size_t row = 0; row < value.shape[0]; ++row) {
      text += row == 0 ? "[" : ", [";
      for (std::size_t column = 0; column < value.shape[1]; ++column)
        text += (column == 0 ? "" : ", ") + element(row * value.shape[1] + column);
      text += "]";
    }
  } else {
    for (std::size_t index = 0; index < value.elements.size(); ++index)
      text += (index == 0 ? "" : ", ") + element(index);
  }
  return text + "]";
}

// The highest N among the connections to ports named LETTER + N (u1, u2, ... or y1, y2, ...); 0 for none.
int highest_numbered(const std::vector<Connection>& connections, char letter) {
  int highest = 0;
  for (const Connection& connection : connections) {
    const std::string& port = connection.port;
    int number = 0;
    if (port.size() >= 2 && port[0] == letter &&
        std::from_chars(port.data() + 1, port.data() + port.size(), number).ec == std::errc{}) {
      highest = std::max(highest, number);
    }
  }
  return highest;
}

// LETTER1 .. LETTERcount.
std::vector<std::string> numbered(char letter, int count) {
  std::vector<std::string> names;
  for (int number = 1; number <= count; ++number) names.push_back(letter + std::to_string(number));
  return names;
}

class DiagramBuilder {
 public:
  DiagramBuilder(const CheckedText& checked, std::string_view text)
      : model_(*checked.model),
        program_(checked.program ? &*checked.program : nullptr),
        places_(checked.file),
        lines_(text),
        names_(model_) {
    if (program_ == nullptr) return;
    for (const model::ProgramBlock& block : program_->blocks) {
      if (block.task == model::at_initialisation) {
        tasks_[block.path] = "constant";
      } else {
        tasks_[block.path] = block.task;
      }
    }
  }

  json diagram() {
    json parameters = json::array();
    for (const model::Parameter& parameter : model_.parameters) {
      json entry = {{"name", parameter.name},
                    {"value", value_text(parameter.value)},
                    {"type", model::type_name(parameter.type)},
                    {"unit", parameter.unit},
                    {"description", parameter.description},
                    {"min", parameter.minimum ? json(*parameter.minimum) : json()},
                    {"max", parameter.maximum ? json(*parameter.maximum) : json()}};
      entry.update(places_.json_of(parameter.location));
      parameters.push_back(std::move(entry));
    }
    return {{"name", model_.name},
            {"base_period_us", model_.base_period_us},
            {"root", system(model_.blocks, "", nullptr)},
            {"parameters", std::move(parameters)}};
  }

 private:
  // The blocks of one scope; `owner` is the subsystem whose inside it is (none at the top).
  json system(const std::vector<Block>& blocks, const std::string& path, const Block* owner) {
    const std::string scope = path.empty() ? "" : path + "/";
    Wires wires{*this, scope, path};
    json system = {{"path", path}, {"inputs", json::array()}, {"outputs", json::array()}, {"blocks", json::array()}};
    if (owner != nullptr) {
      for (const Connection& input : owner->inputs) {
        system["inputs"].push_back({{"port", input.port}, {"signal", input.signal}});
        wires.drive(input.port, {{"system_input", input.port}}, input.location);
      }
    }
    for (const Block& block : blocks) {
      const std::string id = scope + block.name;
      for (const Connection& output : block.outputs)
        wires.drive(output.signal, {{"block", id}, {"port", output.port}}, output.location);
      for (const Connection& input : block.inputs)
        wires.read(input.signal, {{"block", id}, {"port", input.port}}, input.location);
      if (block.trigger.kind == model::Trigger::Kind::edge)
        wires.read(block.trigger.signal, {{"block", id}, {"port", "trigger"}}, block.trigger.location);
      if (!block.enable.empty()) wires.read(block.enable, {{"block", id}, {"port", "enable"}}, block.location);
      system["blocks"].push_back(block_json(block, id));
    }
    if (owner != nullptr) {
      for (const Connection& output : owner->outputs) {
        system["outputs"].push_back({{"port", output.port}, {"signal", output.signal}});
        wires.read(output.port, {{"system_output", output.port}}, output.location);
      }
    }
    system["wires"] = wires.take();
    return system;
  }

  json block_json(const Block& block, const std::string& id) {
    json entry = {{"id", id},
                  {"name", block.name},
                  {"type", block.type},
                  {"end_line", lines_.block_end(block.location)},
                  {"task", task_of(block, id)},
                  {"period", period_json(block.period)},
                  {"inputs", ports(block, true)},
                  {"outputs", ports(block, false)},
                  {"parameters", arguments(block)}};
    entry.update(places_.json_of(block.location));
    if (block.type == "Subsystem") entry["system"] = system(block.blocks, id, &block);
    if (block.trigger.kind != model::Trigger::Kind::none) {
      const model::Trigger& trigger = block.trigger;
      const bool interrupt = trigger.kind == model::Trigger::Kind::interrupt;
      entry["trigger"] = {{"kind", interrupt ? "interrupt" : "edge"},
                          {"interrupt", interrupt ? json(trigger.interrupt) : json()},
                          {"priority", trigger.priority ? json(*trigger.priority) : json()},
                          {"edge", interrupt ? json() : json(trigger.edge)},
                          {"signal", interrupt ? json() : json(trigger.signal)}};
      entry["trigger"].update(places_.json_of(trigger.location));
    }
    if (!block.enable.empty()) entry["enable"] = block.enable;
    if (block.code) entry["code"] = {{"function", block.code->function}, {"file", block.code->file}};
    return entry;
  }

  // A block runs in one task; a subsystem in the task its blocks share, its constants (computed once) aside; none
  // when they differ or are unknown.
  [[nodiscard]] json task_of(const Block& block, const std::string& id) const {
    if (block.type != "Subsystem") {
      const auto found = tasks_.find(id);
      return found == tasks_.end() ? json() : found->second;
    }
    std::optional<json> shared;
    bool constants = false;
    for (const Block& inner : block.blocks) {
      json task = task_of(inner, id + "/" + inner.name);
      if (task == "constant") {
        constants = true;
        continue;
      }
      if (task.is_null() || (shared && *shared != task)) return {};
      shared = std::move(task);
    }
    if (shared) return *shared;
    return constants ? json("constant") : json{};
  }

  static json period_json(const model::Period& period) {
    switch (period.kind) {
      case model::Period::Kind::inherited: return "inherited";
      case model::Period::Kind::base: return "base";
      case model::Period::Kind::constant: return "constant";
      case model::Period::Kind::multiple: return period.multiple;
    }
    return "inherited";
  }

  // The ports the diagram draws: the type's own in its order (connected or not), a variadic block's connected ones
  // (at least two), a Demux's up to the highest connected one and one more to connect (of its eight), a subsystem's
  // or Code block's as written; a connection to a port the type lacks is drawn too, so that the checker's error about
  // it has something to sit on.
  [[nodiscard]] json ports(const Block& block, bool inputs) const {
    const std::vector<Connection>& connections = inputs ? block.inputs : block.outputs;
    std::vector<std::string> names;
    const model::BlockType* type = model::find_block_type(block.type);
    if (type != nullptr && !type->user_defined_ports) {
      if (inputs && type->variadic_inputs) {
        names = numbered('u', std::max(2, highest_numbered(connections, 'u')));
      } else if (!inputs && block.type == "Demux") {
        names = numbered('y', std::min(highest_numbered(connections, 'y') + 1, static_cast<int>(type->outputs.size())));
      } else {
        const auto& fixed = inputs ? type->inputs : type->outputs;
        for (std::string_view name : fixed) names.emplace_back(name);
        if (inputs) {
          for (std::string_view name : type->optional_inputs) names.emplace_back(name);
        }
      }
    }
    for (const Connection& connection : connections) {
      if (std::find(names.begin(), names.end(), connection.port) == names.end()) names.push_back(connection.port);
    }
    json result = json::array();
    for (const std::string& name : names) {
      const auto connected = std::find_if(connections.begin(), connections.end(),
                                          [&](const Connection& connection) { return connection.port == name; });
      json port = {{"port", name}, {"kind", "data"}};
      if (connected != connections.end()) {
        port["signal"] = connected->signal;
        port.update(places_.json_of(connected->location));
      } else {
        port["signal"] = nullptr;
      }
      result.push_back(std::move(port));
    }
    if (inputs && block.trigger.kind == model::Trigger::Kind::edge) {
      json port = {{"port", "trigger"}, {"kind", "trigger"}, {"signal", block.trigger.signal}};
      port.update(places_.json_of(block.trigger.location));
      result.push_back(std::move(port));
    }
    if (inputs && !block.enable.empty()) {
      json port = {{"port", "enable"}, {"kind", "enable"}, {"signal", block.enable}};
      port.update(places_.json_of(block.location));
      result.push_back(std::move(port));
    }
    return result;
  }

  [[nodiscard]] json arguments(const Block& block) const {
    json result = json::array();
    for (const auto& [name, parameter] : block.parameters) {
      const std::string& reference = parameter.reference;  // C++20 lambdas cannot capture a structured binding
      const bool tunable =
          !reference.empty() && std::any_of(model_.parameters.begin(), model_.parameters.end(),
                                            [&](const model::Parameter& model) { return model.name == reference; });
      json entry = {{"name", name},
                    {"text", parameter.text},
                    {"reference", parameter.reference.empty() ? json() : json(parameter.reference)},
                    {"tunable", tunable}};
      entry.update(places_.json_of(parameter.location));
      result.push_back(std::move(entry));
    }
    return result;
  }

  // The signals one system names, in the order they first appear: who drives each and who reads it.
  class Wires {
   public:
    Wires(const DiagramBuilder& builder, std::string scope, std::string path)
        : builder_(builder), scope_(std::move(scope)), path_(std::move(path)) {}

    void drive(const std::string& signal, json source, Location location) {
      Wire& wire = at(signal, location);
      if (wire.source.is_null()) wire.source = std::move(source);
      wire.driver_location = location;
    }
    void read(const std::string& signal, json target, Location location) {
      at(signal, location).targets.push_back(std::move(target));
    }

    json take() {
      json result = json::array();
      for (Wire& wire : wires_) result.push_back(builder_.wire_json(wire, scope_, path_));
      return result;
    }

    struct Wire {
      std::string signal;
      json source;
      json targets = json::array();
      Location first_location;
      std::optional<Location> driver_location;
    };

   private:
    Wire& at(const std::string& signal, Location location) {
      const auto found = index_.find(signal);
      if (found != index_.end()) return wires_[found->second];
      index_[signal] = wires_.size();
      return wires_.emplace_back(Wire{signal, json(), json::array(), location, std::nullopt});
    }

    const DiagramBuilder& builder_;
    std::string scope_;
    std::string path_;
    std::vector<Wire> wires_;
    std::map<std::string, std::size_t> index_;
  };

  [[nodiscard]] json wire_json(const Wires::Wire& wire, const std::string& scope, const std::string& path) const {
    const std::string resolved = names_.model_wide(scope, wire.signal);
    Location location = wire.driver_location.value_or(wire.first_location);
    json entry = {
        {"id", path + ":" + wire.signal}, {"signal", wire.signal},   {"resolved", resolved}, {"measurement", nullptr},
        {"source", wire.source},          {"targets", wire.targets}, {"type", nullptr},      {"unit", ""}};
    if (scope.empty()) {
      const auto declared =
          std::find_if(model_.signals.begin(), model_.signals.end(),
                       [&](const model::SignalDeclaration& declaration) { return declaration.name == wire.signal; });
      if (declared != model_.signals.end()) {
        location = declared->location;
        entry["unit"] = declared->unit;
      }
    }
    if (program_ != nullptr) {
      if (const auto index = program_->find_signal(resolved)) {
        const model::ProgramSignal& signal = program_->signals[*index];
        entry["type"] = model::describe(signal.type);
        entry["unit"] = signal.unit;
        if (signal.measurable) {
          std::string measurement = signal.name;
          std::replace(measurement.begin(), measurement.end(), '/', '.');
          entry["measurement"] = measurement;
        }
      }
    }
    entry.update(places_.json_of(location));
    return entry;
  }

  const model::Model& model_;
  const model::Program* program_;
  Places places_;
  SourceLines lines_;
  model::SignalNames names_;
  std::map<std::string, json> tasks_;  // block path -> task index or "constant"
};

}  // namespace

json tasks_json(const model::Program& program) {
  json tasks = json::array();
  for (std::size_t index = 0; index < program.tasks.size(); ++index) {
    const model::ProgramTask& task = program.tasks[index];
    const bool periodic = task.rate.kind == model::Rate::Kind::periodic;
    tasks.push_back(
        {{"index", index},
         {"name", task.name},
         {"function", model::task_function_name(task)},
         {"kind", periodic ? "periodic" : "interrupt"},
         {"period_us",
          periodic ? json(static_cast<double>(task.rate.multiple) * program.model->base_period_us) : json()},
         {"interrupt", periodic ? json() : json(task.rate.interrupt)},
         {"priority", task.priority ? json(*task.priority) : json()},
         {"blocks", task.outputs.size()}});
  }
  return tasks;
}

namespace {

// The innermost block whose lines in `file` (empty: the open model's) hold `line`, by id; empty when none does. A
// referenced model's blocks lie inside their reference's subsystem but in their own file, so every system is searched.
std::string find_block(const json& system, const std::string& file, int line) {
  for (const json& block : system["blocks"]) {
    if (block.contains("system")) {
      std::string inner = find_block(block["system"], file, line);
      if (!inner.empty()) return inner;
    }
    if (block.value("file", "") == file && line >= block["line"].get<int>() && line <= block["end_line"].get<int>())
      return block["id"].get<std::string>();
  }
  return {};
}

}  // namespace

CheckedText check_text(std::string_view text, const std::string& file) {
  CheckedText checked;
  checked.file = file;
  auto model = model::parse_model(text, file);
  if (!model) {
    checked.diagnostics.push_back(parse_problem(model.error(), file));
    return checked;
  }
  checked.model = std::make_unique<model::Model>(std::move(model).value());
  model::ProgramBuild build = model::build_program(*checked.model);
  checked.diagnostics = std::move(build.diagnostics);
  checked.program = std::move(build.program);
  return checked;
}

json model_view(const CheckedText& checked, std::string_view text) {
  json view = {{"ok", checked.program.has_value()},
               {"diagnostics", json::array()},
               {"diagram", nullptr},
               {"tasks", checked.program ? tasks_json(*checked.program) : json::array()}};
  if (checked.model) view["diagram"] = DiagramBuilder{checked, text}.diagram();
  const Places places{checked.file};
  for (const model::Diagnostic& diagnostic : checked.diagnostics) {
    json entry = {{"severity", diagnostic.severity == model::Diagnostic::Severity::error ? "error" : "warning"},
                  {"file", places.diagnostic_file(diagnostic.location)},
                  {"line", diagnostic.location.line},
                  {"column", diagnostic.location.column},
                  {"message", diagnostic.message},
                  {"hint", diagnostic.hint},
                  {"block", nullptr}};
    if (!view["diagram"].is_null()) {
      const std::string block =
          find_block(view["diagram"]["root"], places.file_of(diagnostic.location), diagnostic.location.line);
      if (!block.empty()) entry["block"] = block;
    }
    view["diagnostics"].push_back(std::move(entry));
  }
  return view;
}

}  // namespace duet::studio
