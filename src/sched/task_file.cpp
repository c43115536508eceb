#include "duet/sched/task_file.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "duet/sched/picoseconds.hpp"
#include "duet/support/text_file.hpp"

namespace duet::sched {
namespace {

// A problem at a node: "file:line: what".
class Reader {
 public:
  explicit Reader(const std::string& file) : file_(file) {}

  [[nodiscard]] Failure at(const YAML::Node& node, const std::string& what) const {
    return Failure{file_ + ":" + std::to_string(node.Mark().line + 1) + ": " + what};
  }

  // Every key of `node` must be one of `known`.
  [[nodiscard]] std::optional<Failure> only(const YAML::Node& node, const std::string& where,
                                            std::initializer_list<const char*> known) const {
    for (const auto& entry : node) {
      const std::string key = entry.first.as<std::string>();
      bool found = false;
      for (const char* name : known) found = found || key == name;
      if (!found) {
        std::string list;
        for (const char* name : known) list += (list.empty() ? "" : ", ") + std::string{name};
        return at(entry.first, where + ": unknown field '" + key + "' (known: " + list + ")");
      }
    }
    return std::nullopt;
  }

  // A time field; `required` or defaulting to `fallback`; never negative, a whole number of picoseconds.
  [[nodiscard]] Result<double> time_field(const YAML::Node& parent, const std::string& where, const char* field,
                                          std::optional<double> fallback) const {
    const YAML::Node node = parent[field];
    if (!node) {
      if (fallback) return *fallback;
      return at(parent, where + ": '" + field + "' is missing");
    }
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
      return at(node, where + ": " + field + ": expected a number, got '" +
                          (node.IsScalar() ? node.Scalar() : "a list or map") + "'");
    }
    if (const auto exact = whole_picoseconds(value); !exact) {
      return at(node, where + ": " + field + ": " + node.Scalar() + " " + exact.error());
    }
    return value;
  }

  [[nodiscard]] Result<int> integer(const YAML::Node& parent, const std::string& where, const char* field, int fallback,
                                    int most) const {
    const YAML::Node node = parent[field];
    if (!node) return fallback;
    int value = 0;
    if (!node.IsScalar() || !YAML::convert<int>::decode(node, value)) {
      return at(node, where + ": " + field + ": expected a whole number, got '" +
                          (node.IsScalar() ? node.Scalar() : "a list or map") + "'");
    }
    if (value < 0 || value > most) {
      return at(node, where + ": " + field + ": " + node.Scalar() + " is outside 0.." + std::to_string(most));
    }
    return value;
  }

 private:
  std::string file_;
};

Result<Core> read_core(const Reader& reader, const YAML::Node& node) {
  Core core;
  if (!node) return core;
  if (!node.IsMap()) return reader.at(node, "core: expected a map of fields");
  if (auto unknown = reader.only(node, "core",
                                 {"priority_bits", "sub_priority_bits", "entry_overhead_us", "exit_overhead_us",
                                  "masked_section_us", "sections"})) {
    return *unknown;
  }
  auto bits = reader.integer(node, "core", "priority_bits", 4, 8);
  if (!bits) return Failure{bits.error()};
  core.priority_bits = bits.value();
  auto sub_bits = reader.integer(node, "core", "sub_priority_bits", 0, core.priority_bits);
  if (!sub_bits) return Failure{sub_bits.error()};
  core.sub_priority_bits = sub_bits.value();
  for (const auto& [field, target] : {std::pair{"entry_overhead_us", &core.entry_overhead},
                                      {"exit_overhead_us", &core.exit_overhead},
                                      {"masked_section_us", &core.masked_section}}) {
    auto value = reader.time_field(node, "core", field, 0.0);
    if (!value) return Failure{value.error()};
    *target = value.value();
  }
  const YAML::Node sections = node["sections"];
  if (sections && !sections.IsSequence()) return reader.at(sections, "core: sections: expected a list");
  const int groups = 1 << (core.priority_bits - core.sub_priority_bits);
  for (std::size_t index = 0; sections && index < sections.size(); ++index) {
    const YAML::Node section = sections[index];
    const std::string where = "core: section " + std::to_string(index + 1);
    if (!section.IsMap()) return reader.at(section, where + ": expected {ceiling, longest_us}");
    if (auto unknown = reader.only(section, where, {"ceiling", "longest_us"})) return *unknown;
    if (!section["ceiling"]) return reader.at(section, where + ": 'ceiling' is missing");
    auto ceiling = reader.integer(section, where, "ceiling", 0, groups - 1);
    if (!ceiling) return Failure{ceiling.error()};
    auto longest = reader.time_field(section, where, "longest_us", std::nullopt);
    if (!longest) return Failure{longest.error()};
    core.sections.push_back({ceiling.value(), longest.value()});
  }
  return core;
}

Result<NvicPriority> read_priority(const Reader& reader, const YAML::Node& node, const std::string& where,
                                   const Core& core) {
  const int groups = 1 << (core.priority_bits - core.sub_priority_bits);
  const int subs = 1 << core.sub_priority_bits;
  NvicPriority priority;
  if (node.IsScalar()) {
    YAML::Node holder;
    holder["group"] = node;
    auto group = reader.integer(holder, where, "group", 0, groups - 1);
    if (!group)
      return reader.at(
          node, where + ": priority: expected a group priority 0.." + std::to_string(groups - 1) + " or {group, sub}");
    priority.group = group.value();
    return priority;
  }
  if (!node.IsMap()) return reader.at(node, where + ": priority: expected a number or {group, sub}");
  if (auto unknown = reader.only(node, where + ": priority", {"group", "sub"})) return *unknown;
  auto group = reader.integer(node, where + ": priority", "group", 0, groups - 1);
  if (!group) return Failure{group.error()};
  auto sub = reader.integer(node, where + ": priority", "sub", 0, subs - 1);
  if (!sub) return Failure{sub.error()};
  return NvicPriority{group.value(), sub.value()};
}

Result<Task> read_task(const Reader& reader, const YAML::Node& node, std::size_t index, const Core& core) {
  std::string where = "task " + std::to_string(index + 1);
  if (!node.IsMap()) return reader.at(node, where + ": expected a map of fields");
  Task task;
  if (!node["name"] || !node["name"].IsScalar() || node["name"].Scalar().empty()) {
    return reader.at(node, where + ": 'name' is missing");
  }
  task.name = node["name"].Scalar();
  where = "task '" + task.name + "'";
  if (auto unknown = reader.only(
          node, where, {"name", "wcet_us", "period_us", "deadline_us", "jitter_us", "source", "irq", "priority"})) {
    return *unknown;
  }
  auto wcet = reader.time_field(node, where, "wcet_us", std::nullopt);
  if (!wcet) return Failure{wcet.error()};
  auto period = reader.time_field(node, where, "period_us", std::nullopt);
  if (!period) return Failure{period.error()};
  auto deadline = reader.time_field(node, where, "deadline_us", period.value());
  if (!deadline) return Failure{deadline.error()};
  auto jitter = reader.time_field(node, where, "jitter_us", 0.0);
  if (!jitter) return Failure{jitter.error()};
  task.wcet = wcet.value();
  task.period = period.value();
  task.deadline = deadline.value();
  task.jitter = jitter.value();
  for (const auto& [field, value] :
       {std::pair{"wcet_us", task.wcet}, {"period_us", task.period}, {"deadline_us", task.deadline}}) {
    if (value == 0) return reader.at(node[field] ? node[field] : node, where + ": " + field + " must be more than 0");
  }
  if (task.wcet > task.period && task.deadline <= task.period) {
    return reader.at(node["wcet_us"], where + ": wcet_us " + node["wcet_us"].Scalar() + " exceeds period_us " +
                                          node["period_us"].Scalar() +
                                          " while the deadline is within the period: it could never be met");
  }
  if (node["source"]) task.source = node["source"].as<std::string>();
  auto irq = reader.integer(node, where, "irq", 0, 495);  // the NVIC's largest IRQ number
  if (!irq) return Failure{irq.error()};
  task.irq = irq.value();
  if (node["priority"]) {
    auto priority = read_priority(reader, node["priority"], where, core);
    if (!priority) return Failure{priority.error()};
    task.priority = priority.value();
  }
  return task;
}

}  // namespace

Result<TaskSet> parse_task_file(std::string_view text, const std::string& file) {
  const Reader reader{file};
  YAML::Node root;
  try {
    root = YAML::Load(std::string{text});
  } catch (const YAML::Exception& error) {
    return Failure{file + ":" + std::to_string(error.mark.line + 1) + ": not YAML: " + error.msg};
  }
  if (!root.IsMap()) return Failure{file + ": expected a map with 'core' and 'tasks'"};
  try {
    if (auto unknown = reader.only(root, "the file", {"core", "tasks"})) return *unknown;
    TaskSet set;
    auto core = read_core(reader, root["core"]);
    if (!core) return Failure{core.error()};
    set.core = core.value();
    const YAML::Node tasks = root["tasks"];
    if (!tasks || !tasks.IsSequence() || tasks.size() == 0)
      return reader.at(root, "'tasks' is missing or empty: expected a list of tasks");
    std::set<std::string> names;
    for (std::size_t index = 0; index < tasks.size(); ++index) {
      auto task = read_task(reader, tasks[index], index, set.core);
      if (!task) return Failure{task.error()};
      if (!names.insert(task.value().name).second) {
        return reader.at(tasks[index], "task '" + task.value().name + "' is named twice");
      }
      set.tasks.push_back(std::move(task).value());
    }
    return set;
  } catch (const YAML::Exception& error) {  // a key that is not a scalar, and the like
    return Failure{file + ":" + std::to_string(error.mark.line + 1) + ": " + error.msg};
  }
}

Result<TaskSet> load_task_file(const std::string& path) {
  auto text = read_text_file(path);
  if (!text) return Failure{text.error()};
  return parse_task_file(text.value(), path);
}

}  // namespace duet::sched
