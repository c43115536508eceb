#include "duet/host/simulated_interrupt_controller.hpp"

#include <tuple>
#include <utility>

namespace duet::host {

SimulatedInterruptController::SimulatedInterruptController(std::size_t line_count) : lines_(line_count) {}

void SimulatedInterruptController::connect(std::size_t line, Priority priority, std::function<void()> handler) {
  lines_.at(line).priority = priority;
  lines_.at(line).handler = std::move(handler);
}

void SimulatedInterruptController::pend(std::size_t line) {
  Line& pended = lines_.at(line);
  if (!pended.handler) return;
  pended.pending = true;
  if (pended.priority.group < running_group_) dispatch();
}

void SimulatedInterruptController::dispatch() {
  for (;;) {
    Line* next = nullptr;
    for (Line& line : lines_) {  // in line order, so that ties go to the lower line number
      if (!line.pending || line.priority.group >= running_group_) continue;
      if (next == nullptr ||
          std::tie(line.priority.group, line.priority.sub) < std::tie(next->priority.group, next->priority.sub)) {
        next = &line;
      }
    }
    if (next == nullptr) return;
    next->pending = false;
    const unsigned interrupted_group = std::exchange(running_group_, next->priority.group);
    next->handler();
    running_group_ = interrupted_group;
  }
}

}  // namespace duet::host
