#include "duet/sched/report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "duet/sched/utilization.hpp"

namespace duet::sched {
namespace {

std::string microseconds(double value) {
  if (value == unbounded) return "inf";
  std::ostringstream out;
  out << std::fixed << std::setprecision(value < 10 ? 4 : value < 1000 ? 3 : 1) << value;
  return out.str();
}

std::string priority_text(const NvicPriority& priority) {
  return std::to_string(priority.group) + "." + std::to_string(priority.sub);
}

// XML text: the task names come from the user's file.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

std::string text_report(const TaskSet& set, const Analysis& analysis) {
  std::ostringstream out;
  std::size_t name_width = 4;
  for (const Task& task : set.tasks) name_width = std::max(name_width, task.name.size());
  const auto column = [&out](const std::string& text, int width) { out << std::setw(width) << text; };
  out << std::left << std::setw(static_cast<int>(name_width)) << "task" << std::right;
  for (const char* heading : {"prio", "C us", "T us", "D us", "J us", "u", "B us", "R us", "slack us"}) {
    column(heading, 11);
  }
  out << "  verdict\n";
  std::size_t missed = 0;
  for (std::size_t i = 0; i < set.tasks.size(); ++i) {
    const Task& task = set.tasks[i];
    const TaskResponse& response = analysis.tasks[i];
    out << std::left << std::setw(static_cast<int>(name_width)) << task.name << std::right;
    column(priority_text(*task.priority), 11);
    column(microseconds(response.cost), 11);
    column(microseconds(task.period), 11);
    column(microseconds(task.deadline), 11);
    column(microseconds(task.jitter), 11);
    std::ostringstream u;
    u << std::fixed << std::setprecision(4) << response.cost / task.period;
    column(u.str(), 11);
    column(microseconds(response.blocking), 11);
    column(microseconds(response.response), 11);
    column(response.response == unbounded ? "-inf" : microseconds(response.slack()), 11);
    out << "  " << (response.meets_deadline() ? "meets" : "MISSES") << '\n';
    missed += response.meets_deadline() ? 0U : 1U;
  }
  const Utilization u = utilization(set);
  out << std::fixed << std::setprecision(4) << "\nutilization C/T " << u.by_period << " (Liu & Layland bound "
      << u.liu_layland_bound << ": " << (u.passes_liu_layland() ? "passes" : "fails") << "), hyperbolic product "
      << u.hyperbolic_product << " (" << (u.passes_hyperbolic() ? "passes" : "fails") << "), C/D " << u.by_deadline
      << " (" << (u.passes_deadline_check() ? "passes" : "fails") << "); these are sufficient tests only\n";
  out << (missed == 0 ? "schedulable: every task meets its deadline (exact response-time analysis)\n"
                      : "NOT schedulable: " + std::to_string(missed) + " of " + std::to_string(set.tasks.size()) +
                            " tasks miss their deadlines\n");
  out << "\nNVIC priorities (group.sub; lower is more urgent), for the model file:\npriorities:\n";
  for (const Task& task : set.tasks) {
    out << "  " << task.name << ": {group: " << task.priority->group << ", sub: " << task.priority->sub << "}\n";
  }
  return out.str();
}

std::string json_report(const TaskSet& set, const Analysis& analysis) {
  nlohmann::json tasks = nlohmann::json::array();
  const auto number = [](double value) { return value == unbounded ? nlohmann::json(nullptr) : nlohmann::json(value); };
  for (std::size_t i = 0; i < set.tasks.size(); ++i) {
    const Task& task = set.tasks[i];
    const TaskResponse& response = analysis.tasks[i];
    tasks.push_back({{"name", task.name},
                     {"source", task.source},
                     {"priority", {{"group", task.priority->group}, {"sub", task.priority->sub}}},
                     {"wcet_us", response.cost},
                     {"period_us", task.period},
                     {"deadline_us", task.deadline},
                     {"jitter_us", task.jitter},
                     {"utilization", response.cost / task.period},
                     {"blocking_us", response.blocking},
                     {"response_us", number(response.response)},
                     {"slack_us", number(response.slack())},
                     {"worst_job", response.worst_job},
                     {"meets_deadline", response.meets_deadline()}});
  }
  const Utilization u = utilization(set);
  return nlohmann::json{{"schedulable", analysis.schedulable()},
                        {"tasks", tasks},
                        {"utilization",
                         {{"by_period", u.by_period},
                          {"by_deadline", u.by_deadline},
                          {"liu_layland_bound", u.liu_layland_bound},
                          {"hyperbolic_product", u.hyperbolic_product}}}}
      .dump(2);
}

std::string timeline_svg(const TaskSet& set, const Analysis& analysis) {
  double window = unbounded;
  for (const Task& task : set.tasks) window = std::min(window, task.deadline);
  for (const TaskResponse& response : analysis.tasks) {
    if (response.response != unbounded) window = std::max(window, response.response);
  }
  window *= 1.05;
  const std::vector<SimulatedJob> jobs = simulate(set, critical_instant(set, window));

  constexpr double left = 160, right = 30, top = 30, row = 28, width = 960;
  const double scale = (width - left - right) / window;
  const double height = top + row * static_cast<double>(set.tasks.size()) + 40;
  const auto x = [&](double t) { return left + std::clamp(t, 0.0, window) * scale; };
  std::ostringstream svg;
  svg << std::fixed << std::setprecision(2);
  svg << R"(<svg xmlns="http://www.w3.org/2000/svg" width=")" << width << R"(" height=")" << height
      << R"(" font-family="sans-serif" font-size="12">)" << '\n';
  svg << R"(<rect width="100%" height="100%" fill="white"/>)" << '\n';
  svg << R"(<text x=")" << left << R"(" y="18">Critical instant: every task released at 0 (jitter held back), )"
      << "NVIC semantics; window " << microseconds(window) << " us</text>\n";
  for (std::size_t i = 0; i < set.tasks.size(); ++i) {
    const double y = top + row * static_cast<double>(i);
    svg << R"(<text x="4" y=")" << y + 17 << R"(">)" << escaped(set.tasks[i].name) << " ("
        << priority_text(*set.tasks[i].priority) << ")</text>\n";
    svg << R"(<line x1=")" << left << R"(" y1=")" << y + row - 4 << R"(" x2=")" << width - right << R"(" y2=")"
        << y + row - 4 << R"(" stroke="#bbb"/>)" << '\n';
  }
  for (const SimulatedJob& job : jobs) {
    if (job.arrival >= window) continue;
    const double y = top + row * static_cast<double>(job.task);
    const bool late = job.response() > set.tasks[job.task].deadline;
    for (const auto& [from, to] : job.runs) {
      if (from >= window) continue;
      svg << R"(<rect x=")" << x(from) << R"(" y=")" << y + 6 << R"(" width=")" << std::max(0.5, x(to) - x(from))
          << R"(" height=")" << row - 10 << R"(" fill=")" << (late ? "#d33" : "#4a7fc1") << R"("/>)" << '\n';
    }
    svg << R"(<path d="M)" << x(job.arrival) << ' ' << y + row - 4 << " v-20\" stroke=\"black\"/>\n";  // arrival
    const double deadline = job.arrival + set.tasks[job.task].deadline;
    if (deadline <= window) {
      svg << R"(<path d="M)" << x(deadline) << ' ' << y + 4 << " v20\" stroke=\"#d33\" stroke-dasharray=\"3,2\"/>\n";
    }
  }
  const double axis = top + row * static_cast<double>(set.tasks.size()) + 14;
  // Ticks at a round step: 1, 2 or 5 times a power of ten, about ten of them.
  const double rough = window / 10;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  const double step = rough <= power       ? power
                      : rough <= 2 * power ? 2 * power
                      : rough <= 5 * power ? 5 * power
                                           : 10 * power;
  for (double t = 0; t <= window; t += step) {
    std::ostringstream label;
    label << std::defaultfloat << std::setprecision(6) << t;
    svg << R"(<text x=")" << x(t) - 6 << R"(" y=")" << axis << R"(">)" << label.str() << "</text>\n";
  }
  svg << R"(<text x=")" << left << R"(" y=")" << axis + 18
      << R"(">us; bars: running (red: a job that misses its deadline); black: arrival; dashed red: deadline</text>)"
      << "\n</svg>\n";
  return svg.str();
}

}  // namespace duet::sched
