#include "duet/sched/response_time.hpp"

#include <algorithm>
#include <compare>
#include <optional>
#include <string>
#include <tuple>

#include "duet/sched/picoseconds.hpp"
#include "natural.hpp"

namespace duet::sched {
namespace {

// A task in whole picoseconds; `cost` is C with the core's entry and exit overheads.
struct ExactTask {
  Picoseconds cost = 0;
  Picoseconds period = 0;
  Picoseconds deadline = 0;
  Picoseconds jitter = 0;
};

// An iterate beyond this is taken for a busy period that does not end: it keeps t + J and the counts of jobs within
// 64 bits. Only a level whose hyperperiod or busy period is longer (about 53 days) reaches it.
constexpr Picoseconds longest_busy_period = Picoseconds{1} << 62;

// Jobs of a task released in [0, t] (the release at t included), with jitter: they may come J early.
Picoseconds released_up_to(Picoseconds t, const ExactTask& task) { return (t + task.jitter) / task.period + 1; }
// Jobs released in [0, t).
Picoseconds released_before(Picoseconds t, const ExactTask& task) {
  const Picoseconds span = t + task.jitter;
  return span / task.period + (span % task.period == 0 ? 0 : 1);
}

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

// `base` plus the cost of `jobs(task)` jobs of each of `tasks`; none if that does not fit in 64 bits.
template <typename Jobs>
std::optional<Picoseconds> plus_jobs(Picoseconds base, const std::vector<ExactTask>& exact,
                                     const std::vector<std::size_t>& tasks, Jobs&& jobs) {
  Picoseconds total = base;
  for (std::size_t j : tasks) {
    Picoseconds work = 0;
    if (__builtin_mul_overflow(jobs(exact[j]), exact[j].cost, &work) || __builtin_add_overflow(total, work, &total)) {
      return std::nullopt;
    }
  }
  return total;
}

// Iterates `next` from `start` to its least fixed point. Every recurrence here is a non-decreasing step function of
// whole picoseconds that starts at or below its fixed point, so the iterates rise to it by at least 1 ps a step and
// stop there. None past `longest_busy_period`.
template <typename Next>
std::optional<Picoseconds> least_fixed_point(Picoseconds start, Next&& next) {
  Picoseconds value = start;
  while (true) {
    const std::optional<Picoseconds> following = next(value);
    if (!following || *following > longest_busy_period) return std::nullopt;
    if (*following <= value) return value;
    value = *following;
  }
}

// The utilization of `level` against 1, exactly: sum_j C_j / T_j as one fraction over the product of the periods.
std::strong_ordering utilization_against_one(const std::vector<ExactTask>& exact,
                                             const std::vector<std::size_t>& level) {
  Natural numerator{0};
  Natural denominator{1};
  for (std::size_t j : level) {
    const auto cost = static_cast<std::uint64_t>(exact[j].cost);
    const auto period = static_cast<std::uint64_t>(exact[j].period);
    // n/d + C/T = (n T + C d) / (d T)
    Natural added = denominator;
    added *= cost;
    numerator *= period;
    numerator += added;
    denominator *= period;
  }
  return numerator <=> denominator;
}

// Whether the level-i busy period ends. Below utilization 1 the work done outgrows the work released; at exactly 1 it
// ends by the hyperperiod, where every release of the level comes again with all earlier work done, unless blocking
// or jitter adds work that is never caught up; above 1 it never ends.
bool busy_period_ends(const std::vector<ExactTask>& exact, const std::vector<std::size_t>& level,
                      Picoseconds blocking) {
  const std::strong_ordering utilization = utilization_against_one(exact, level);
  if (utilization != std::strong_ordering::equal) return utilization == std::strong_ordering::less;
  return blocking == 0 && std::all_of(level.begin(), level.end(), [&](std::size_t j) { return exact[j].jitter == 0; });
}

// The longest section that can delay a handler of `group`: every masked section, and each section at a ceiling as
// urgent as the group or more. Which task holds a section is not known, so one held by a more urgent task (whose
// preemption is counted already) is counted too: safe, at worst pessimistic.
Picoseconds section_blocking(const TaskSet& set, int group, Picoseconds masked_section,
                             const std::vector<Picoseconds>& sections) {
  Picoseconds blocking = masked_section;
  for (std::size_t s = 0; s < sections.size(); ++s) {
    if (set.core.sections[s].ceiling <= group) blocking = std::max(blocking, sections[s]);
  }
  return blocking;
}

TaskResponse analyse_task(const TaskSet& set, std::size_t i, const std::vector<ExactTask>& exact, Picoseconds section) {
  const ExactTask& task = exact[i];
  const Roles roles = roles_of(set, i);
  Picoseconds blocking = section;
  for (std::size_t j : roles.blocking) blocking = std::max(blocking, exact[j].cost);
  TaskResponse result;
  result.cost = to_microseconds(task.cost);
  result.deadline = to_microseconds(task.deadline);
  result.blocking = to_microseconds(blocking);
  result.response = unbounded;

  // The level-i busy period: i and everything dispatched before it, after the blocking.
  std::vector<std::size_t> level = roles.dispatched_first;
  level.push_back(i);
  if (!busy_period_ends(exact, level, blocking)) return result;
  const auto busy = least_fixed_point(blocking + task.cost, [&](Picoseconds w) {
    return plus_jobs(blocking, exact, level, [w](const ExactTask& t) { return released_before(w, t); });
  });
  if (!busy) return result;
  result.jobs = static_cast<std::size_t>(std::max<Picoseconds>(released_before(*busy, task), 1));
  Picoseconds worst = 0;
  for (std::size_t q = 0; q < result.jobs; ++q) {
    const Picoseconds before_start = blocking + static_cast<Picoseconds>(q) * task.cost;
    // Job q starts once the blocking, the earlier jobs and every job dispatched before it (released up to then) ran.
    const auto start = least_fixed_point(before_start, [&](Picoseconds s) {
      return plus_jobs(before_start, exact, roles.dispatched_first,
                       [s](const ExactTask& t) { return released_up_to(s, t); });
    });
    if (!start) return result;
    // Once started, only a more urgent group preempts it: their jobs released after the start.
    const auto finish = least_fixed_point(*start + task.cost, [&](Picoseconds f) {
      return plus_jobs(*start + task.cost, exact, roles.preempting,
                       [&](const ExactTask& t) { return released_before(f, t) - released_up_to(*start, t); });
    });
    if (!finish) return result;
    const Picoseconds response = *finish - static_cast<Picoseconds>(q) * task.period + task.jitter;
    if (response > worst) {
      worst = response;
      result.worst_job = q;
    }
  }
  result.response = to_microseconds(worst);
  return result;
}

// A time in the task set, in picoseconds: `name` says where in errors.
struct TimeField {
  double microseconds;
  std::string name;
  Picoseconds* exact;
};

std::optional<Failure> convert(std::initializer_list<TimeField> fields) {
  for (const TimeField& field : fields) {
    auto time = whole_picoseconds(field.microseconds);
    if (!time) return Failure{field.name + " " + time.error()};
    *field.exact = time.value();
  }
  return std::nullopt;
}

}  // namespace

bool dispatched_before(const TaskSet& set, std::size_t a, std::size_t b) {
  const Task& first = set.tasks[a];
  const Task& second = set.tasks[b];
  return std::tuple{first.priority->group, first.priority->sub, first.irq, a} <
         std::tuple{second.priority->group, second.priority->sub, second.irq, b};
}

Result<Analysis> analyse(const TaskSet& set) {
  Picoseconds entry = 0;
  Picoseconds exit = 0;
  Picoseconds masked_section = 0;
  if (auto failure = convert({{set.core.entry_overhead, "core: entry_overhead_us", &entry},
                              {set.core.exit_overhead, "core: exit_overhead_us", &exit},
                              {set.core.masked_section, "core: masked_section_us", &masked_section}})) {
    return *failure;
  }
  std::vector<ExactTask> exact(set.tasks.size());
  for (std::size_t i = 0; i < set.tasks.size(); ++i) {
    const Task& task = set.tasks[i];
    const std::string where = "task '" + task.name + "': ";
    if (!task.priority) {
      return Failure{"task '" + task.name + "' has no priority: give it one, or let duet assign them"};
    }
    ExactTask& into = exact[i];
    Picoseconds wcet = 0;
    if (auto failure = convert({{task.wcet, where + "wcet_us", &wcet},
                                {task.period, where + "period_us", &into.period},
                                {task.deadline, where + "deadline_us", &into.deadline},
                                {task.jitter, where + "jitter_us", &into.jitter}})) {
      return *failure;
    }
    if (into.period == 0) return Failure{where + "period_us must be more than 0"};
    into.cost = wcet + entry + exit;  // each below 2^61: the sum fits
  }
  std::vector<Picoseconds> sections(set.core.sections.size());
  for (std::size_t s = 0; s < sections.size(); ++s) {
    if (auto failure = convert({{set.core.sections[s].longest,
                                 "core: section " + std::to_string(s + 1) + ": longest_us", &sections[s]}})) {
      return *failure;
    }
  }
  Analysis analysis;
  for (std::size_t i = 0; i < set.tasks.size(); ++i) {
    const Picoseconds blocking = section_blocking(set, set.tasks[i].priority->group, masked_section, sections);
    analysis.tasks.push_back(analyse_task(set, i, exact, blocking));
  }
  return analysis;
}

}  // namespace duet::sched
