#include "duet/studio/generation.hpp"

#include "duet/model/generate.hpp"
#include "duet/model/task_set_file.hpp"
#include "duet/sched/report.hpp"
#include "duet/sched/response_time.hpp"
#include "duet/sched/task_file.hpp"

namespace duet::studio {

using nlohmann::json;

namespace {

json schedulability(const model::Program& program, const TaskTimes& times) {
  auto task_file = model::task_set_file(program, times.wcet_us, times.interarrival_us);
  if (!task_file) return {{"verdict", "not analysed"}, {"schedulable", nullptr}, {"report", task_file.error()}};
  auto set = sched::parse_task_file(task_file.value(), "the model's tasks");
  if (!set) return {{"verdict", "not analysed"}, {"schedulable", nullptr}, {"report", set.error()}};
  auto analysis = sched::analyse(set.value());
  if (!analysis) return {{"verdict", "not analysed"}, {"schedulable", nullptr}, {"report", analysis.error()}};
  const bool schedulable = analysis.value().schedulable();
  return {{"verdict", schedulable ? "schedulable" : "not schedulable"},
          {"schedulable", schedulable},
          {"report", sched::text_report(set.value(), analysis.value())},
          {"task_file", task_file.value()}};
}

}  // namespace

Result<json> generated_message(const CheckedText& checked, const std::string& source, const TaskTimes& times) {
  const model::Program& program = *checked.program;
  auto files = model::generate(program, source);
  if (!files) return Failure{files.error()};
  json message = {{"type", "generated"},
                  {"files", json::array()},
                  {"tasks", tasks_json(program)},
                  {"schedulability", schedulability(program, times)}};
  for (const model::GeneratedFile& file : files.value())
    message["files"].push_back({{"name", file.name}, {"text", file.text}});
  return message;
}

}  // namespace duet::studio
