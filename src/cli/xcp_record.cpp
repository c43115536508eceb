#include "xcp_record.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <span>
#include <stdexcept>

#include "duet/plot/figure.hpp"
#include "duet/xcp/host/values.hpp"

namespace duet::cli::xcp_actions {
namespace {

using namespace duet::xcp::host;

// A write during a recording. XCP has one master, and the bridge refuses a second while `record` is connected, so
// the recording's own session sends it.
struct TimedWrite {
  double at_s = 0;  // after the recording started, by the PC's clock (as --duration counts)
  ParameterWrite write;
};

Result<std::vector<TimedWrite>> parse_timed_writes(const Session& session, const XcpOptions& options) {
  std::vector<TimedWrite> writes;
  for (const std::string& text : options.timed_writes) {
    const std::size_t colon = text.find(':');
    double at_s = -1;
    try {
      std::size_t used = 0;
      if (colon != std::string::npos) at_s = std::stod(text.substr(0, colon), &used);
      if (used != colon) at_s = -1;
    } catch (const std::exception&) {
      at_s = -1;
    }
    if (!(at_s >= 0)) return Failure{"'" + text + "': expected SECONDS:NAME=VALUE"};
    if (at_s >= options.duration_s) return Failure{"'" + text + "': after the recording's end (--duration)"};
    auto write = parse_assignment(session, text.substr(colon + 1));
    if (!write) return Failure{write.error()};
    writes.push_back({at_s, std::move(write).value()});
  }
  std::stable_sort(writes.begin(), writes.end(),
                   [](const TimedWrite& a, const TimedWrite& b) { return a.at_s < b.at_s; });
  return writes;
}

}  // namespace

ExitCode run_record(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true);
  if (!session) return report({session.error()}, streams);
  if (!session.value().a2l) return report({"record needs --a2l FILE"}, streams);
  const A2lDescription& a2l = *session.value().a2l;
  Master& master = *session.value().master;
  const EventInfo* event = nullptr;
  for (const EventInfo& info : a2l.events) {
    if (info.name == options.event || std::to_string(info.channel) == options.event) event = &info;
  }
  if (event == nullptr)
    return report({"'" + options.event + "' is no event in the A2L (give its name or number)"}, streams);
  if (options.event_time && event->time_cycle == 0)
    return report({"--event-time: the A2L gives event '" + event->name + "' no period"}, streams);
  std::vector<const Variable*> recorded;
  DaqListSetup list{.event = event->channel, .prescaler = 1};
  plot::Figure figure{a2l.module + ", event '" + event->name + "'", "s", {}, {}};
  for (const std::string& name : options.signals) {
    auto variable = variable_named(session.value(), name);
    if (!variable) return report({variable.error()}, streams);
    const Variable& found = *variable.value();
    recorded.push_back(&found);
    for (std::uint32_t element = 0; element < found.count; ++element) {
      list.entries.push_back({found.extension,
                              found.address + element * static_cast<std::uint32_t>(size_of(found.type)),
                              static_cast<std::uint8_t>(size_of(found.type))});
      figure.series.push_back(
          {found.name + (found.count > 1 ? "[" + std::to_string(element) + "]" : ""), found.unit, {}});
    }
  }
  auto writes = parse_timed_writes(session.value(), options);
  if (!writes) return report({writes.error()}, streams);

  std::ofstream file;
  if (!options.output.empty()) {
    file.open(options.output);
    if (!file) return report({options.output + ": cannot be written"}, streams);
  }
  const bool plotting = !options.plot.empty();
  std::ofstream plot_file;
  if (plotting) {  // opened now, so that a bad path fails before the recording rather than after it
    plot_file.open(options.plot);
    if (!plot_file) return report({options.plot + ": cannot be written"}, streams);
  }
  if (Status started = master.start_daq({list}); !started) return report({started.error()}, streams);
  std::ostream& csv = options.output.empty() ? streams.out : file;
  csv << "time_s";
  for (const plot::Series& column : figure.series) csv << ',' << column.name;
  csv << '\n';

  const double tick_seconds = a2l.timestamp_tick_s();
  const double event_period_s = event->period_s();
  const bool terminal = ::isatty(STDERR_FILENO) != 0 && &streams.err == &std::cerr;
  const auto start = std::chrono::steady_clock::now();
  const auto end = start + std::chrono::duration<double>(options.duration_s);
  std::optional<std::uint32_t> first_timestamp;
  std::uint64_t samples = 0;
  double last_time_s = 0;
  std::size_t next_write = 0;
  for (auto now = start; now < end; now = std::chrono::steady_clock::now()) {
    const double elapsed = std::chrono::duration<double>(now - start).count();
    for (; next_write < writes.value().size() && writes.value()[next_write].at_s <= elapsed; ++next_write) {
      const ParameterWrite& write = writes.value()[next_write].write;
      if (Status written = apply(master, write); !written) return report({written.error()}, streams);
      streams.err << (terminal ? "\n" : "") << "wrote " << write.assignment << " after " << std::fixed
                  << std::setprecision(2) << elapsed << " s";
      if (samples != 0) streams.err << " (the last sample so far at " << std::setprecision(3) << last_time_s << " s)";
      streams.err << '\n';
    }
    auto wait = std::chrono::milliseconds{50};
    if (next_write < writes.value().size()) {
      const auto until_write = std::chrono::duration<double>(writes.value()[next_write].at_s - elapsed);
      wait = std::min(wait, std::chrono::ceil<std::chrono::milliseconds>(until_write));
    }
    auto received = master.receive_samples(wait);
    if (!received) return report({received.error()}, streams);
    for (const DaqSample& sample : received.value()) {
      if (!first_timestamp) first_timestamp = sample.timestamp;
      last_time_s = options.event_time ? static_cast<double>(samples) * event_period_s
                                       : static_cast<double>(sample.timestamp - *first_timestamp) * tick_seconds;
      csv << std::setprecision(9) << last_time_s;
      if (plotting) figure.time.push_back(last_time_s);
      std::size_t at = 0;
      std::size_t column = 0;
      for (const Variable* variable : recorded) {
        const std::size_t bytes = size_of(variable->type) * variable->count;
        for (double value : decode(*variable, std::span{sample.bytes}.subspan(at, bytes))) {
          csv << ',' << std::setprecision(10) << value;
          if (plotting) figure.series[column].values.push_back(value);
          ++column;
        }
        at += bytes;
      }
      csv << '\n';
      ++samples;
    }
    if (terminal) {
      streams.err << "\rrecording " << std::fixed << std::setprecision(1) << elapsed << " / " << options.duration_s
                  << " s, " << samples << " samples" << std::flush;
    }
  }
  (void)master.stop_daq();
  (void)master.disconnect();
  if (terminal) streams.err << '\n';
  const std::uint64_t lost = master.channel().counter_gaps();
  streams.err << "recorded " << samples << " samples of " << recorded.size() << " signals on event '" << options.event
              << "' (" << master.overload_events() << " overloads, " << lost << " lost packets)\n";
  if (options.event_time && (lost != 0 || master.overload_events() != 0)) {
    streams.err << "duet xcp: samples were lost, so the times --event-time counted after the first loss are early\n";
  }
  if (plotting) {
    plot_file << plot::to_svg(figure);
    plot_file.close();
    if (!plot_file) return report({options.plot + ": cannot be written"}, streams);
  }
  return ExitCode::success;
}

}  // namespace duet::cli::xcp_actions
