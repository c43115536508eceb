#pragma once
// The executive's account on the console, in the key=value lines that `duet pil` and tests read (docs/LINK.md,
// "Processor in the loop"): a duet-status line (model time, ticks, core load, overruns), then a duet-task line per
// task (activations, overruns, net execution times in cycles of the board's 25 MHz timer), and a duet-section line per
// priority ceiling (by its group) at which a section was measured (the longest, in the same cycles).

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/rt/ceiling.hpp"
#include "duet/rt/task_statistics.hpp"
#include "duet/rt/task_table.hpp"

namespace duet::mps2_an386 {

template <typename Executive>
std::uint64_t total_overruns(const Executive& executive, const rt::ModelDescription& model) {
  std::uint64_t overruns = 0;
  for (std::size_t task = 0; task < model.tasks.size(); ++task) overruns += executive.statistics(task).overruns;
  return overruns;
}

// `write_line(std::string_view)` takes each line, its newline included.
template <typename Executive, typename WriteLine>
void write_executive_report(const Executive& executive, const rt::ModelDescription& model, WriteLine write_line) {
  TextBuffer<240> line;
  const auto emit = [&line, &write_line] {
    line.append('\n');
    write_line(line.view());
    line.clear();
  };
  const std::uint64_t ticks = executive.ticks();
  const std::uint64_t milliseconds = ticks * model.base_period_ns / 1'000'000U;
  line.append("duet-status time_s=").append(milliseconds / 1000U).append('.');
  for (std::uint64_t digit = 100; digit > 0; digit /= 10)
    line.append(static_cast<char>('0' + milliseconds / digit % 10));
  line.append(" ticks=").append(ticks).append(" busy_ppm=").append(executive.load().busy_ppm());
  line.append(" overruns=").append(total_overruns(executive, model));
  emit();
  for (std::size_t task = 0; task < model.tasks.size(); ++task) {
    const rt::TaskStatistics& statistics = executive.statistics(task);
    line.append("duet-task index=").append(task).append(" name=");
    for (const char character : model.tasks[task].name) line.append(character == ' ' ? '_' : character);
    line.append(" activations=").append(statistics.activations).append(" overruns=").append(statistics.overruns);
    line.append(" min_cycles=").append(statistics.activations == 0 ? 0U : statistics.min_cycles);
    line.append(" mean_cycles=").append(statistics.mean_cycles());
    line.append(" max_cycles=").append(statistics.max_cycles);
    emit();
  }
  // The longest section measured at each ceiling (by its group) that had one: blocking for `duet sched`.
  const std::size_t group_step = std::size_t{1} << model.sub_priority_bits;
  for (std::size_t priority = 0; priority < rt::SectionTiming::levels; priority += group_step) {
    const std::uint32_t longest = executive.longest_section(rt::Ceiling{static_cast<std::uint8_t>(priority)});
    if (longest == 0) continue;
    line.append("duet-section ceiling=").append(priority >> model.sub_priority_bits);
    line.append(" longest_cycles=").append(longest);
    emit();
  }
}

// The same on the console.
template <typename Executive>
void write_executive_report(const Executive& executive, const rt::ModelDescription& model) {
  write_executive_report(executive, model, [](std::string_view line) { cortex_m::console_write(line); });
}

}  // namespace duet::mps2_an386
