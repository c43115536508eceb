#include "duet/sched/simulator.hpp"

#include <algorithm>
#include <deque>

#include "duet/sched/response_time.hpp"

namespace duet::sched {

std::vector<SimulatedJob> simulate(const TaskSet& set, std::vector<Release> releases) {
  std::sort(releases.begin(), releases.end(), [](const Release& a, const Release& b) { return a.release < b.release; });
  const std::size_t count = set.tasks.size();
  std::vector<double> costs;
  for (const Task& task : set.tasks) costs.push_back(task.wcet + set.core.entry_overhead + set.core.exit_overhead);

  struct Running {
    std::size_t task;
    SimulatedJob job;
    double remaining;
    double resumed;  // when its current run began
  };
  std::vector<std::deque<SimulatedJob>> pending(count);  // per task, oldest first
  std::vector<Running> stack;                            // the running handler on top, the preempted below
  std::vector<SimulatedJob> finished;
  std::size_t next_release = 0;
  double now = releases.empty() ? 0 : releases.front().release;

  // The most urgent pending task that may run now: it must preempt the running handler, if any.
  const auto eligible = [&]() -> std::optional<std::size_t> {
    std::optional<std::size_t> best;
    for (std::size_t task = 0; task < count; ++task) {
      if (pending[task].empty()) continue;
      if (!best || dispatched_before(set, task, *best)) best = task;
    }
    if (best && !stack.empty() && set.tasks[*best].priority->group >= set.tasks[stack.back().task].priority->group) {
      return std::nullopt;
    }
    return best;
  };

  while (next_release < releases.size() || !stack.empty() ||
         std::any_of(pending.begin(), pending.end(), [](const auto& jobs) { return !jobs.empty(); })) {
    while (next_release < releases.size() && releases[next_release].release <= now) {
      const Release& release = releases[next_release++];
      pending[release.task].push_back({release.task, release.arrival, 0, 0});
    }
    while (const auto task = eligible()) {
      SimulatedJob job = pending[*task].front();
      pending[*task].pop_front();
      job.start = now;
      if (!stack.empty() && stack.back().resumed < now) stack.back().job.runs.emplace_back(stack.back().resumed, now);
      stack.push_back({*task, job, costs[*task], now});
    }
    const double next_event = next_release < releases.size() ? releases[next_release].release : unbounded;
    if (stack.empty()) {
      now = next_event;
      continue;
    }
    Running& running = stack.back();
    if (now + running.remaining <= next_event) {
      now += running.remaining;
      running.job.finish = now;
      running.job.runs.emplace_back(running.resumed, now);
      finished.push_back(running.job);
      stack.pop_back();
      if (!stack.empty()) stack.back().resumed = now;
    } else {
      running.remaining -= next_event - now;
      now = next_event;
    }
  }
  return finished;
}

std::vector<Release> critical_instant(const TaskSet& set, double until, const std::vector<double>& offsets) {
  std::vector<Release> releases;
  for (std::size_t task = 0; task < set.tasks.size(); ++task) {
    const Task& t = set.tasks[task];
    const double offset = task < offsets.size() ? offsets[task] : 0.0;
    releases.push_back({task, offset - t.jitter, offset});
    for (double arrival = offset - t.jitter + t.period; arrival < until; arrival += t.period) {
      releases.push_back({task, arrival, std::max(arrival, offset)});
    }
  }
  return releases;
}

std::vector<double> largest_responses(const TaskSet& set, const std::vector<SimulatedJob>& jobs) {
  std::vector<double> largest(set.tasks.size(), 0.0);
  for (const SimulatedJob& job : jobs) largest[job.task] = std::max(largest[job.task], job.response());
  return largest;
}

}  // namespace duet::sched
