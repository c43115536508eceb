#include "duet/monitor/executive_account_layout.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "duet/dashboard/executive_status.hpp"
#include "duet/model/generate.hpp"

namespace duet::monitor {
namespace {

constexpr std::string_view prefix = "executive.";  // the account's names: executive.FIELD, executive.TASK.FIELD
constexpr std::array<std::string_view, 4> account_fields{"ticks", "busy_ppm", "overruns", "cycle_hz"};
constexpr std::array<std::string_view, 5> task_fields{"activations", "overruns", "min_cycles", "mean_cycles",
                                                      "max_cycles"};

template <std::size_t size>
std::optional<std::size_t> index_of(const std::array<std::string_view, size>& names, std::string_view name) {
  const auto found = std::find(names.begin(), names.end(), name);
  if (found == names.end()) return std::nullopt;
  return static_cast<std::size_t>(found - names.begin());
}

std::uint32_t word_at(std::span<const std::uint8_t> bytes, std::optional<std::uint32_t> offset) {
  if (!offset || *offset + 4U > bytes.size()) return 0;
  std::uint32_t word = 0;
  for (std::uint32_t byte = 0; byte < 4; ++byte) word |= std::uint32_t{bytes[*offset + byte]} << (8U * byte);
  return word;
}

}  // namespace

std::optional<ExecutiveAccountLayout> ExecutiveAccountLayout::from(const xcp::host::A2lDescription& a2l) {
  const auto segment = std::find_if(a2l.memory.begin(), a2l.memory.end(), [](const xcp::host::MemoryInfo& info) {
    return info.name == model::executive_segment;
  });
  if (segment == a2l.memory.end()) return std::nullopt;
  ExecutiveAccountLayout layout;
  layout.segment_ = *segment;
  for (const xcp::host::Variable& measurement : a2l.measurements) {
    if (!measurement.name.starts_with(prefix) || measurement.type != xcp::host::DataType::uint32 ||
        measurement.address < segment->address || measurement.address + 4U > segment->address + segment->size) {
      continue;
    }
    const std::uint32_t offset = measurement.address - segment->address;
    const std::string_view rest = std::string_view{measurement.name}.substr(prefix.size());
    const std::size_t dot = rest.rfind('.');
    if (dot == std::string_view::npos) {
      if (auto field = index_of(account_fields, rest)) layout.offsets_[*field] = offset;
      continue;
    }
    const auto field = index_of(task_fields, rest.substr(dot + 1));
    if (!field) continue;
    const std::string name{rest.substr(0, dot)};
    auto task = std::find_if(layout.tasks_.begin(), layout.tasks_.end(), [&](const Task& t) { return t.name == name; });
    if (task == layout.tasks_.end()) task = layout.tasks_.insert(task, Task{name, {}});
    task->offsets[*field] = offset;
  }
  if (!layout.offsets_[1]) return std::nullopt;  // no core load: not an account duet knows
  // duet gen numbers the events as the task table and names the account's tasks after them: show the events' names.
  if (a2l.events.size() == layout.tasks_.size()) {
    for (std::size_t task = 0; task < layout.tasks_.size(); ++task) layout.tasks_[task].name = a2l.events[task].name;
  }
  return layout;
}

nlohmann::json ExecutiveAccountLayout::decode(std::span<const std::uint8_t> bytes, std::uint32_t base_period_ns) const {
  app_channel::host::ExecutiveReport report{.ticks = word_at(bytes, offsets_[0]),
                                            .base_period_ns = base_period_ns,
                                            .busy_ppm = word_at(bytes, offsets_[1]),
                                            .overruns = word_at(bytes, offsets_[2]),
                                            .cycle_hz = word_at(bytes, offsets_[3]),
                                            .tasks = {}};
  for (const Task& task : tasks_) {
    report.tasks.push_back({.name = task.name,
                            .activations = word_at(bytes, task.offsets[0]),
                            .overruns = word_at(bytes, task.offsets[1]),
                            .min_cycles = word_at(bytes, task.offsets[2]),
                            .mean_cycles = word_at(bytes, task.offsets[3]),
                            .max_cycles = word_at(bytes, task.offsets[4])});
  }
  return dashboard::executive_status(report);
}

}  // namespace duet::monitor
