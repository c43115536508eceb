#pragma once
// Task-set files (YAML, docs/SCHEDULING.md): the core's NVIC and overheads, and the tasks. Errors name the file, the
// line and the field.

#include <string>
#include <string_view>

#include "duet/sched/task_set.hpp"
#include "duet/support/result.hpp"

namespace duet::sched {

// `text` is the file's content; `file` names it in errors.
[[nodiscard]] Result<TaskSet> parse_task_file(std::string_view text, const std::string& file);
[[nodiscard]] Result<TaskSet> load_task_file(const std::string& path);

}  // namespace duet::sched
