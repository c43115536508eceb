#pragma once
// duet studio's `generated` message (docs/STUDIO.md): what `duet gen` writes for the model, its task table, and
// `duet sched`'s verdict on it. The verdict needs each task's execution time and each interrupt task's shortest
// time between triggers, which no model holds: the page gives them, or a connected target's measured maxima stand in
// for the execution times; without them the verdict says which are missing.

#include <nlohmann/json.hpp>

#include <map>
#include <string>

#include "duet/studio/model_view.hpp"
#include "duet/support/result.hpp"

namespace duet::studio {

struct TaskTimes {
  std::map<std::string, double> wcet_us;          // by task function name: step_rate_1, task_EXTI8
  std::map<std::string, double> interarrival_us;  // interrupt tasks
};

// `checked` must have a program. `source` names the model in the files' first lines.
[[nodiscard]] Result<nlohmann::json> generated_message(const CheckedText& checked, const std::string& source,
                                                       const TaskTimes& times);

}  // namespace duet::studio
