#pragma once
// A model's tasks as a task file for `duet sched` (docs/SCHEDULING.md): the periods and priorities come from the
// model; what a model cannot know — each task's execution time, measured on the target (the executive's statistics),
// and the shortest time between an interrupt task's triggers — the caller gives, by the task's step function's name
// (step_rate_1, task_UART0_RX).

#include <map>
#include <string>

#include "duet/model/program.hpp"
#include "duet/support/result.hpp"

namespace duet::model {

// The name a task has in the task file and in generated code: step_rate_10, task_DMA2_Stream2.
[[nodiscard]] std::string task_function_name(const ProgramTask& task);

// Every task needs its execution time; every interrupt task its minimum inter-arrival time. Deadlines are the periods.
// The periodic rates run in the base timer's interrupt (single-tasking), so they are one source there.
// `sections_us` holds the longest critical section measured at each priority ceiling, by its group (the executive's
// Executive::longest_section): the core's `sections`, blocking for the tasks at and below the ceiling.
[[nodiscard]] Result<std::string> task_set_file(const Program& program, const std::map<std::string, double>& wcet_us,
                                                const std::map<std::string, double>& interarrival_us,
                                                const std::map<int, double>& sections_us = {});

}  // namespace duet::model
