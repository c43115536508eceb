#include "firmware_console.hpp"

#include <charconv>
#include <map>
#include <vector>

namespace duet::cli {
namespace {

// A line's KEY=VALUE words; a word without '=' is kept with an empty value, to be refused if it is asked for.
class Fields {
 public:
  Fields(std::string_view keyword, std::string_view words) : keyword_(keyword) {
    while (!words.empty()) {
      const std::size_t start = words.find_first_not_of(' ');
      if (start == std::string_view::npos) break;
      words.remove_prefix(start);
      const std::string_view word = words.substr(0, words.find(' '));
      words.remove_prefix(word.size());
      const std::size_t equals = word.find('=');
      const std::string_view key = word.substr(0, equals);
      if (!values_.emplace(key, equals == std::string_view::npos ? "" : word.substr(equals + 1)).second) {
        problem_ = problem_.empty() ? keyword_ + ": '" + std::string{key} + "' twice" : problem_;
      } else {
        order_.push_back(key);
      }
    }
  }

  void text(std::string_view key, std::string& value) {
    const std::string_view* found = find(key);
    if (found != nullptr) value = *found;
  }
  template <typename Number>
  void number(std::string_view key, Number& value) {
    const std::string_view* found = find(key);
    if (found == nullptr) return;
    const auto [end, error] = std::from_chars(found->data(), found->data() + found->size(), value);
    if (error != std::errc{} || end != found->data() + found->size() || found->empty()) {
      fail("'" + std::string{key} + "' is not a number: '" + std::string{*found} + "'");
    }
  }
  [[nodiscard]] const std::string& problem() const { return problem_; }
  // Every field, as a number, in the line's order.
  [[nodiscard]] std::vector<std::pair<std::string, std::uint64_t>> numbers() {
    std::vector<std::pair<std::string, std::uint64_t>> all;
    for (const std::string_view key : order_) {
      std::uint64_t value = 0;
      number(key, value);
      all.emplace_back(key, value);
    }
    return all;
  }

 private:
  const std::string_view* find(std::string_view key) {
    const auto found = values_.find(key);
    if (found == values_.end() || found->second.empty()) {
      fail("no '" + std::string{key} + "'");
      return nullptr;
    }
    return &found->second;
  }
  void fail(const std::string& what) {
    if (problem_.empty()) problem_ = keyword_ + ": " + what;
  }

  std::string keyword_;
  std::map<std::string_view, std::string_view, std::less<>> values_;
  std::vector<std::string_view> order_;
  std::string problem_;
};

constexpr std::uint64_t most_tasks = 256;
constexpr std::uint64_t last_group = 15;  // NVIC groups are 0 to 15 with 4 priority bits

template <typename Line>
ConsoleLine checked(Line line, const Fields& fields) {
  if (!fields.problem().empty()) return MalformedLine{fields.problem()};
  return line;
}

}  // namespace

ConsoleLine parse_console_line(std::string_view line) {
  if (line.ends_with('\r')) line.remove_suffix(1);
  const std::string_view keyword = line.substr(0, line.find(' '));
  const std::string_view words = line.substr(keyword.size());
  if (keyword == "duet-status") {
    Fields fields{keyword, words};
    FirmwareStatus status;
    fields.number("time_s", status.time_s);
    fields.number("ticks", status.ticks);
    fields.number("busy_ppm", status.busy_ppm);
    fields.number("overruns", status.overruns);
    return checked(status, fields);
  }
  if (keyword == "duet-task") {
    Fields fields{keyword, words};
    FirmwareTask task;
    fields.number("index", task.index);
    fields.text("name", task.name);
    fields.number("activations", task.activations);
    fields.number("overruns", task.overruns);
    fields.number("min_cycles", task.min_cycles);
    fields.number("mean_cycles", task.mean_cycles);
    fields.number("max_cycles", task.max_cycles);
    // Indices come from the firmware's task table: small, and a garbled one must not make the report huge.
    if (fields.problem().empty() && task.index >= most_tasks) {
      return MalformedLine{"duet-task: index " + std::to_string(task.index) + " is beyond " +
                           std::to_string(most_tasks - 1)};
    }
    return checked(task, fields);
  }
  if (keyword == "duet-section") {
    Fields fields{keyword, words};
    FirmwareSection section;
    fields.number("ceiling", section.ceiling);
    fields.number("longest_cycles", section.longest_cycles);
    if (fields.problem().empty() && section.ceiling > last_group) {
      return MalformedLine{"duet-section: ceiling " + std::to_string(section.ceiling) + " is beyond " +
                           std::to_string(last_group)};
    }
    return checked(section, fields);
  }
  if (keyword == "duet-end") {
    Fields fields{keyword, words};
    FirmwareEnd end;
    fields.text("reason", end.reason);
    fields.number("ticks", end.ticks);
    fields.number("overruns", end.overruns);
    return checked(end, fields);
  }
  if (keyword == "duet-lost") {
    Fields fields{keyword, words};
    FirmwareLosses losses{fields.numbers()};
    return checked(losses, fields);
  }
  return ConsoleText{std::string{line}};
}

void take(FirmwareReport& report, const ConsoleLine& line) {
  if (const auto* status = std::get_if<FirmwareStatus>(&line)) {
    report.status = *status;
  } else if (const auto* task = std::get_if<FirmwareTask>(&line)) {
    if (report.tasks.size() <= task->index) report.tasks.resize(task->index + 1);
    report.tasks[task->index] = *task;
  } else if (const auto* section = std::get_if<FirmwareSection>(&line)) {
    report.sections[section->ceiling] = section->longest_cycles;
  } else if (const auto* end = std::get_if<FirmwareEnd>(&line)) {
    report.end = *end;
  } else if (const auto* losses = std::get_if<FirmwareLosses>(&line)) {
    report.losses = *losses;
  }
}

}  // namespace duet::cli
