#include "xcp_record.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <span>
#include <sstream>
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

// What became of the packets: "(2 overloads, 0 lost packets, 3 discarded: 1 of unknown ODTs, ...)".
std::string packet_summary(const PacketCounters& counters) {
  const std::uint64_t discarded =
      counters.unknown_identification + counters.too_short + counters.incomplete + counters.unexpected;
  std::string summary = std::to_string(counters.overload_events) + " overloads, " +
                        std::to_string(counters.counter_gaps) + " lost packets, " + std::to_string(discarded) +
                        " discarded";
  if (discarded != 0) {
    summary += ": " + std::to_string(counters.unknown_identification) + " of unknown ODTs, " +
               std::to_string(counters.too_short) + " too short, " + std::to_string(counters.incomplete) +
               " of incomplete samples, " + std::to_string(counters.unexpected) + " unexpected";
  }
  if (counters.padded != 0) summary += "; " + std::to_string(counters.padded) + " with fill bytes";
  return summary;
}

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
  auto session = open_session(options, true, streams.err);
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
  // Times by the slave's timestamps, unless asked otherwise or there are none.
  const bool timestamped = !options.event_time && master.seconds_per_tick() > 0;
  if (!options.event_time && !timestamped && event->time_cycle == 0) {
    return report({"the slave sends no timestamps and the A2L gives event '" + event->name +
                   "' no period: the samples cannot be timed"},
                  streams);
  }

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

  const double tick_seconds = master.seconds_per_tick();
  const double event_period_s = event->period_s();
  if (!options.event_time && !timestamped) {
    streams.err << "duet xcp: the slave sends no timestamps: the samples are timed by the event's period\n";
  }
  const bool terminal = ::isatty(STDERR_FILENO) != 0 && &streams.err == &std::cerr;
  const auto start = std::chrono::steady_clock::now();
  const auto end = start + std::chrono::duration<double>(options.duration_s);
  std::optional<std::int64_t> first_ticks;
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
      if (!first_ticks) first_ticks = sample.ticks;
      last_time_s = timestamped ? static_cast<double>(sample.ticks - *first_ticks) * tick_seconds
                                : static_cast<double>(samples) * event_period_s;
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
    if (!csv) break;  // the disk is full or the reader went away: said below
    if (terminal) {
      streams.err << "\rrecording " << std::fixed << std::setprecision(1) << elapsed << " / " << options.duration_s
                  << " s, " << samples << " samples" << std::flush;
    }
  }
  const Status stopped = master.stop_daq();
  const Status disconnected = master.disconnect();
  if (terminal) streams.err << '\n';
  const PacketCounters counters = master.counters();
  streams.err << "recorded " << samples << " samples of " << recorded.size() << " signals on event '" << options.event
              << "' (" << packet_summary(counters) << ")\n";
  if (options.event_time && counters.lost() != 0) {
    streams.err << "duet xcp: samples were lost, so the times --event-time counted after the first loss are early\n";
  }
  if (plotting) {
    plot_file << plot::to_svg(figure);
    plot_file.close();
    if (!plot_file) return report({options.plot + ": cannot be written"}, streams);
  }
  csv.flush();
  if (!csv) {
    return report({(options.output.empty() ? std::string{"standard output"} : options.output) +
                   ": writing the samples failed after " + std::to_string(samples) + " of them"},
                  streams);
  }
  if (!stopped) return report({stopped.error()}, streams);
  if (!disconnected) return report({disconnected.error()}, streams);
  if (samples == 0) {
    std::ostringstream problem;
    problem << "no sample came in " << options.duration_s << " s: is event '" << event->name << "' running?";
    return report({problem.str()}, streams);
  }
  if (counters.lost() != 0) return report({"samples were lost (see the counts above)"}, streams);
  return ExitCode::success;
}

}  // namespace duet::cli::xcp_actions
