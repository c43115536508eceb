#pragma once
// For tests: the thesis' task sets (thesis tables 2.1, 4.6 and 4.9: each task's period, execution time and deadline).

#include <string>

#include "duet/sched/task_set.hpp"

namespace duet::sched {

// The robot's 13 interrupt tasks: table 4.9's T, C, D in microseconds, table 4.6's sources.
inline TaskSet thesis_robot_tasks() {
  struct Row {
    double period, wcet, deadline;
    const char* source;
  };
  const Row rows[] = {
      {1000, 99.818, 500, "TIM7"},         {997.47, 46.467, 500, "EXTI"},   {997.62, 5.4812, 500, "DMA SPI RX"},
      {997.91, 4.0167, 500, "DMA SPI TX"}, {500, 6.8316, 100, "TIM1"},      {501.57, 4.1124, 50, "TIM4"},
      {501.57, 4.1124, 50, "TIM2"},        {1000000, 2.9357, 1000, "IPCC"}, {1000000, 4.6819, 1000, "DMA ADC"},
      {1000000, 4.6437, 1000, "DMA ADC"},  {100000, 6.4102, 100, "TIM5"},   {100000, 6.4102, 100, "TIM5"},
      {8907.7, 1.2778, 1000, "IPCC"}};
  TaskSet set;
  int number = 0;
  for (const Row& row : rows) {
    Task task;
    task.name = "task " + std::to_string(number++);
    task.period = row.period;
    task.wcet = row.wcet;
    task.deadline = row.deadline;
    task.source = row.source;
    set.tasks.push_back(task);
  }
  return set;
}

// Tasks from (C, T) pairs with D = T, no source; `priorities` in the same order if given (group priorities).
inline TaskSet tasks_of(std::initializer_list<std::pair<double, double>> wcet_and_period) {
  TaskSet set;
  for (const auto& [wcet, period] : wcet_and_period) {
    Task task;
    task.name = "t" + std::to_string(set.tasks.size());
    task.wcet = wcet;
    task.period = period;
    task.deadline = period;
    set.tasks.push_back(task);
  }
  return set;
}

// Distinct group priorities in the given order: the first task most urgent.
inline TaskSet in_order(TaskSet set) {
  for (std::size_t i = 0; i < set.tasks.size(); ++i) set.tasks[i].priority = NvicPriority{static_cast<int>(i), 0};
  return set;
}

}  // namespace duet::sched
