#include "duet/sched/priority_assignment.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <string>

#include "duet/sched/response_time.hpp"

namespace duet::sched {
namespace {

// The tasks grouped by interrupt source (a task without a source is a handler of its own), in the set's order.
std::vector<std::vector<std::size_t>> handlers(const TaskSet& set) {
  std::vector<std::vector<std::size_t>> result;
  std::map<std::string, std::size_t> by_source;
  for (std::size_t i = 0; i < set.tasks.size(); ++i) {
    const std::string& source = set.tasks[i].source;
    if (!source.empty()) {
      const auto [found, added] = by_source.try_emplace(source, result.size());
      if (!added) {
        result[found->second].push_back(i);
        continue;
      }
    }
    result.push_back({i});
  }
  return result;
}

}  // namespace

std::vector<NvicPriority> deadline_monotonic(const TaskSet& set, int first_level) {
  std::vector<std::size_t> order(set.tasks.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto density = [&set](std::size_t i) { return set.tasks[i].wcet / set.tasks[i].deadline; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (set.tasks[a].deadline != set.tasks[b].deadline) return set.tasks[a].deadline < set.tasks[b].deadline;
    return density(a) > density(b);
  });
  std::vector<NvicPriority> priorities(set.tasks.size());
  std::map<std::string, int> level_of_source;
  int level = first_level - 1;
  for (std::size_t position = 0; position < order.size(); ++position) {
    const std::size_t i = order[position];
    const std::string& source = set.tasks[i].source;
    if (const auto found = level_of_source.find(source); !source.empty() && found != level_of_source.end()) {
      priorities[i].group = found->second;
      continue;
    }
    const bool same_as_previous = position > 0 && set.tasks[order[position - 1]].deadline == set.tasks[i].deadline &&
                                  density(order[position - 1]) == density(i);
    if (!same_as_previous) ++level;
    priorities[i].group = same_as_previous ? priorities[order[position - 1]].group : level;
    if (!source.empty()) level_of_source.emplace(source, priorities[i].group);
  }
  return priorities;
}

std::optional<std::vector<NvicPriority>> optimal_priorities(const TaskSet& set, int first_level) {
  const std::vector<std::vector<std::size_t>> all = handlers(set);
  std::vector<bool> assigned(all.size(), false);
  std::vector<NvicPriority> priorities(set.tasks.size());
  const int levels = static_cast<int>(all.size());
  for (int level = first_level + levels - 1; level >= first_level; --level) {
    bool found = false;
    for (std::size_t handler = 0; handler < all.size() && !found; ++handler) {
      if (assigned[handler]) continue;
      // Try `handler` at `level`, every other unassigned one more urgent (their order does not matter to it).
      TaskSet trial = set;
      for (std::size_t other = 0; other < all.size(); ++other) {
        for (std::size_t i : all[other]) {
          trial.tasks[i].priority = assigned[other]    ? priorities[i]
                                    : other == handler ? NvicPriority{level, 0}
                                                       : NvicPriority{first_level - 1, 0};
        }
      }
      const Analysis analysis = analyse(trial).value();
      found = std::all_of(all[handler].begin(), all[handler].end(),
                          [&](std::size_t i) { return analysis.tasks[i].meets_deadline(); });
      if (found) {
        assigned[handler] = true;
        for (std::size_t i : all[handler]) priorities[i] = {level, 0};
      }
    }
    if (!found) return std::nullopt;
  }
  return priorities;
}

std::optional<LevelFit> fit_to_levels(const TaskSet& set, int levels, int first_level) {
  // Each task's rank among the distinct group priorities, most urgent 0.
  std::vector<int> groups;
  for (const Task& task : set.tasks) groups.push_back(task.priority->group);
  std::vector<int> distinct = groups;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  std::vector<int> rank(set.tasks.size());
  for (std::size_t i = 0; i < set.tasks.size(); ++i) {
    rank[i] = static_cast<int>(std::lower_bound(distinct.begin(), distinct.end(), groups[i]) - distinct.begin());
  }
  const auto priorities_of = [&](const std::vector<int>& ranks) {
    std::vector<NvicPriority> priorities;
    for (std::size_t i = 0; i < set.tasks.size(); ++i)
      priorities.push_back({first_level + ranks[i], set.tasks[i].priority->sub});
    return priorities;
  };
  std::vector<int> original = rank;
  int count = static_cast<int>(distinct.size());
  while (count > levels) {
    bool merged = false;
    for (int upper = count - 2; upper >= 0 && !merged; --upper) {  // merge rank upper + 1 into upper
      std::vector<int> trial = rank;
      for (int& r : trial) r = r > upper ? r - 1 : r;
      if (analyse(with_priorities(set, priorities_of(trial))).value().schedulable()) {
        rank = trial;
        merged = true;
      }
    }
    if (!merged) return std::nullopt;
    --count;
  }
  LevelFit fit;
  fit.priorities = priorities_of(rank);
  // Tasks that now share a level but did not before.
  std::map<int, std::vector<std::size_t>> by_level;
  for (std::size_t i = 0; i < rank.size(); ++i) by_level[rank[i]].push_back(i);
  for (const auto& [level, tasks] : by_level) {
    for (std::size_t i : tasks) {
      if (original[i] != original[tasks.front()]) {
        fit.shared.push_back(tasks);
        break;
      }
    }
  }
  return fit;
}

TaskSet with_priorities(TaskSet set, const std::vector<NvicPriority>& priorities) {
  for (std::size_t i = 0; i < set.tasks.size() && i < priorities.size(); ++i) set.tasks[i].priority = priorities[i];
  return set;
}

}  // namespace duet::sched
