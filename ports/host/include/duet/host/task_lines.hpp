#pragma once
// How the host ports wire a model's tasks to a SimulatedInterruptController: task i uses line i with the task's
// priority; line 0 is the base timer, lines of the slower rates are their software interrupts, the rest are the
// interrupt tasks' triggers.

#include <cstddef>

#include "duet/host/simulated_interrupt_controller.hpp"
#include "duet/rt/task_table.hpp"

namespace duet::host {

template <typename Executive>
void connect_task_lines(SimulatedInterruptController& interrupts, const rt::ModelDescription& model,
                        Executive& executive) {
  const std::size_t rates = rt::rate_count(model);
  for (std::size_t task = 0; task < model.tasks.size(); ++task) {
    const rt::InterruptPriority priority = model.tasks[task].priority;
    const SimulatedInterruptController::Priority line_priority{priority.group, priority.sub};
    if (task == 0) {
      interrupts.connect(task, line_priority, [&executive] { executive.on_base_tick(); });
    } else if (task < rates) {
      interrupts.connect(task, line_priority, [&executive, task] { executive.on_rate_interrupt(task); });
    } else {
      interrupts.connect(task, line_priority, [&executive, task] { executive.on_interrupt_task(task); });
    }
  }
}

}  // namespace duet::host
