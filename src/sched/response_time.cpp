#include "duet/sched/response_time.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace duet::sched {
namespace {

// Fixed-point iterations stop here: a busy period this long, or this many steps, is taken not to end.
constexpr int most_iterations = 100000;

// Jobs of a task released in [0, t] (the release at t included), with jitter: they may come J early.
double released_up_to(double t, const Task& task) { return std::floor((t + task.jitter) / task.period) + 1.0; }
// Jobs released in [0, t).
double released_before(double t, const Task& task) { return std::ceil((t + task.jitter) / task.period); }

struct Roles {
  std::vector<std::size_t> dispatched_first;  // hp(i): dispatched before i when both are pending
  std::vector<std::size_t> preempting;        // of those, the ones of a more urgent group: they preempt i
  std::vector<std::size_t> blocking;          // dispatched after i but of i's group: once started, they finish
};

Roles roles_of(const TaskSet& set, std::size_t i) {
  Roles roles;
  const int group = set.tasks[i].priority->group;
  for (std::size_t j = 0; j < set.tasks.size(); ++j) {
    if (j == i) continue;
    const int other = set.tasks[j].priority->group;
    if (dispatched_before(set, j, i)) {
      roles.dispatched_first.push_back(j);
      if (other < group) roles.preempting.push_back(j);
    } else if (other == group) {
      roles.blocking.push_back(j);
    }
  }
  return roles;
}

// Iterates `next` from `start` to its fixed point; `unbounded` if it grows past `horizon` or does not settle.
template <typename Next>
double fixed_point(double start, double horizon, Next&& next) {
  double value = start;
  for (int iteration = 0; iteration < most_iterations; ++iteration) {
    const double following = next(value);
    if (following > horizon) return unbounded;
    if (following <= value) return value;
    value = following;
  }
  return unbounded;
}

TaskResponse analyse_task(const TaskSet& set, std::size_t i, const std::vector<double>& costs) {
  const Task& task = set.tasks[i];
  const Roles roles = roles_of(set, i);
  TaskResponse result;
  result.cost = costs[i];
  result.deadline = task.deadline;
  result.blocking = set.core.masked_section;
  for (std::size_t j : roles.blocking) result.blocking = std::max(result.blocking, costs[j]);

  // The level-i busy period: i and everything dispatched before it, after the blocking.
  double level_utilization = costs[i] / task.period;
  for (std::size_t j : roles.dispatched_first) level_utilization += costs[j] / set.tasks[j].period;
  double longest_period = task.period + task.jitter;
  for (const Task& other : set.tasks) longest_period = std::max(longest_period, other.period + other.jitter);
  // With level utilization below 1 the busy period ends within a bounded multiple of the periods; this horizon is
  // generous (it only stops a diverging iteration).
  const double horizon = level_utilization < 1.0 ? 1e6 * longest_period : 0.0;
  if (level_utilization >= 1.0) {  // work arrives at least as fast as it is done: the busy period never ends
    result.response = unbounded;
    return result;
  }
  const double busy = fixed_point(result.blocking + costs[i], horizon, [&](double w) {
    double next = result.blocking + released_before(w, task) * costs[i];
    for (std::size_t j : roles.dispatched_first) next += released_before(w, set.tasks[j]) * costs[j];
    return next;
  });
  if (busy == unbounded) {
    result.response = unbounded;
    return result;
  }
  const auto jobs = static_cast<std::size_t>(std::ceil((busy + task.jitter) / task.period));
  result.jobs = std::max<std::size_t>(jobs, 1);
  for (std::size_t q = 0; q < result.jobs; ++q) {
    const double earlier_jobs = static_cast<double>(q) * costs[i];
    // Job q starts once the blocking, the earlier jobs and every job dispatched before it (released up to then) ran.
    const double start = fixed_point(result.blocking + earlier_jobs, horizon, [&](double s) {
      double next = result.blocking + earlier_jobs;
      for (std::size_t j : roles.dispatched_first) next += released_up_to(s, set.tasks[j]) * costs[j];
      return next;
    });
    if (start == unbounded) {
      result.response = unbounded;
      return result;
    }
    // Once started, only a more urgent group preempts it: their jobs released after the start.
    const double finish = fixed_point(start + costs[i], horizon, [&](double f) {
      double next = start + costs[i];
      for (std::size_t j : roles.preempting) {
        next += (released_before(f, set.tasks[j]) - released_up_to(start, set.tasks[j])) * costs[j];
      }
      return next;
    });
    if (finish == unbounded) {
      result.response = unbounded;
      return result;
    }
    const double response = finish - static_cast<double>(q) * task.period + task.jitter;
    if (response > result.response) {
      result.response = response;
      result.worst_job = q;
    }
  }
  return result;
}

}  // namespace

bool dispatched_before(const TaskSet& set, std::size_t a, std::size_t b) {
  const Task& first = set.tasks[a];
  const Task& second = set.tasks[b];
  return std::tuple{first.priority->group, first.priority->sub, first.irq, a} <
         std::tuple{second.priority->group, second.priority->sub, second.irq, b};
}

Result<Analysis> analyse(const TaskSet& set) {
  for (const Task& task : set.tasks) {
    if (!task.priority) {
      return Failure{"task '" + task.name + "' has no priority: give it one, or let duet assign them"};
    }
  }
  std::vector<double> costs;
  for (const Task& task : set.tasks) costs.push_back(task.wcet + set.core.entry_overhead + set.core.exit_overhead);
  Analysis analysis;
  for (std::size_t i = 0; i < set.tasks.size(); ++i) analysis.tasks.push_back(analyse_task(set, i, costs));
  return analysis;
}

}  // namespace duet::sched
