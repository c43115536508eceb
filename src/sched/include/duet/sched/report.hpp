#pragma once
// What `duet sched` prints: a table per task, the utilization tests, the priorities in the model files' form; JSON
// for scripts; a timeline picture (SVG) of the worst-case window.

#include <string>
#include <vector>

#include "duet/sched/response_time.hpp"
#include "duet/sched/simulator.hpp"
#include "duet/sched/task_set.hpp"

namespace duet::sched {

[[nodiscard]] std::string text_report(const TaskSet& set, const Analysis& analysis);
[[nodiscard]] std::string json_report(const TaskSet& set, const Analysis& analysis);

// The critical instant simulated over the worst-case window: the largest finite response time (at least the
// shortest deadline), one row per task, its releases, runs and deadlines.
[[nodiscard]] std::string timeline_svg(const TaskSet& set, const Analysis& analysis);

}  // namespace duet::sched
