#include "duet/model/task_set_file.hpp"

#include "duet/model/data_type.hpp"
#include "duet/model/simulation.hpp"
#include "duet/support/number_text.hpp"

namespace duet::model {

std::string task_function_name(const ProgramTask& task) {
  if (task.rate.kind == Rate::Kind::periodic) return "step_rate_" + std::to_string(task.rate.multiple);
  return "task_" + task.rate.interrupt;
}

Result<std::string> task_set_file(const Program& program, const std::map<std::string, double>& wcet_us,
                                  const std::map<std::string, double>& interarrival_us,
                                  const std::map<int, double>& sections_us) {
  auto priorities = task_priorities(program);
  if (!priorities) return Failure{priorities.error()};
  std::string known;
  for (const ProgramTask& task : program.tasks) known += (known.empty() ? "" : ", ") + task_function_name(task);
  for (const auto& given : {wcet_us, interarrival_us}) {
    for (const auto& [name, value] : given) {
      const bool found = std::any_of(program.tasks.begin(), program.tasks.end(),
                                     [&name](const ProgramTask& task) { return task_function_name(task) == name; });
      if (!found) return Failure{"the model has no task '" + name + "' (its tasks: " + known + ")"};
      if (!(value > 0)) return Failure{"task '" + name + "': times are microseconds above 0"};
    }
  }
  std::string text =
      "# The tasks of " + program.model->name + " for duet sched (docs/SCHEDULING.md), written by duet model tasks.\n";
  std::string sections;
  for (const auto& [ceiling, longest] : sections_us) {
    if (ceiling < 0 || ceiling > 15)
      return Failure{"section ceiling " + std::to_string(ceiling) + ": groups are 0 to 15"};
    if (!(longest > 0))
      return Failure{"section at ceiling " + std::to_string(ceiling) + ": times are microseconds above 0"};
    sections += std::string{sections.empty() ? "" : ", "} + "{ceiling: " + std::to_string(ceiling) +
                ", longest_us: " + shortest_text(longest) + "}";
  }
  text += "core: {priority_bits: 4, sub_priority_bits: 0" + (sections.empty() ? "" : ", sections: [" + sections + "]") +
          "}\ntasks:\n";
  for (std::size_t index = 0; index < program.tasks.size(); ++index) {
    const ProgramTask& task = program.tasks[index];
    const std::string name = task_function_name(task);
    const auto wcet = wcet_us.find(name);
    if (wcet == wcet_us.end()) {
      return Failure{"task '" + name + "' needs its execution time: --wcet " + name +
                     "=MICROSECONDS (the executive measures it on the target: docs/EXECUTIVE.md)"};
    }
    double period = 0;
    std::string source = "base timer";
    if (task.rate.kind == Rate::Kind::periodic) {
      period = static_cast<double>(task.rate.multiple) * program.model->base_period_us;
    } else {
      const auto interarrival = interarrival_us.find(name);
      if (interarrival == interarrival_us.end()) {
        return Failure{"interrupt task '" + name + "' needs the shortest time between its triggers: --interarrival " +
                       name + "=MICROSECONDS"};
      }
      period = interarrival->second;
      source = task.rate.interrupt;
    }
    text += "  - {name: " + name + ", source: " + source + ", period_us: " + shortest_text(period) +
            ", wcet_us: " + shortest_text(wcet->second) +
            ", priority: {group: " + std::to_string(priorities.value().priorities[index].group) + ", sub: 0}}\n";
  }
  return text;
}

}  // namespace duet::model
