#include "xcp_record.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>

#include "duet/mdf4_recording/daq_file.hpp"
#include "duet/plot/figure.hpp"
#include "duet/xcp/host/values.hpp"
#include "stop_signals.hpp"

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

// One DAQ list: an event and the signals it samples, and where their columns start in the CSV and the plot.
struct RecordedList {
  const EventInfo* event = nullptr;
  std::vector<const Variable*> variables;
  std::size_t first_column = 0;
  std::size_t columns = 0;
  std::uint64_t samples = 0;     // complete ones
  std::uint64_t incomplete = 0;  // reported by the master, timed but without values
};

Result<const EventInfo*> event_named(const A2lDescription& a2l, const std::string& name) {
  for (const EventInfo& info : a2l.events) {
    if (info.name == name || std::to_string(info.channel) == name) return &info;
  }
  return Failure{"'" + name + "' is no event in the A2L (give its name or number)"};
}

// The DAQ lists of the --signal options, NAME@EVENT or NAME on --event, a list per event in the order first named.
Result<std::vector<RecordedList>> recorded_lists(const Session& session, const XcpOptions& options) {
  std::vector<RecordedList> lists;
  for (const std::string& text : options.signals) {
    const std::size_t at = text.rfind('@');
    const std::string event_name = at == std::string::npos ? options.event : text.substr(at + 1);
    if (event_name.empty()) return Failure{"--signal '" + text + "': give NAME@EVENT, or --event for all"};
    auto event = event_named(*session.a2l, event_name);
    if (!event) return Failure{event.error()};
    auto variable = variable_named(session, text.substr(0, at));
    if (!variable) return Failure{variable.error()};
    auto list = std::find_if(lists.begin(), lists.end(),
                             [&event](const RecordedList& known) { return known.event == event.value(); });
    if (list == lists.end()) list = lists.insert(lists.end(), RecordedList{.event = event.value()});
    list->variables.push_back(variable.value());
  }
  std::size_t column = 0;
  for (RecordedList& list : lists) {
    list.first_column = column;
    for (const Variable* variable : list.variables) list.columns += variable->count;
    column += list.columns;
  }
  return lists;
}

std::string event_names(const std::vector<RecordedList>& lists) {
  std::string names;
  for (const RecordedList& list : lists) names += (names.empty() ? "'" : ", '") + list.event->name + "'";
  return names;
}

// "42 samples of 2 signals on event '1 ms'", an event after the other.
std::string sample_counts(const std::vector<RecordedList>& lists) {
  std::string counts;
  for (const RecordedList& list : lists) {
    counts += (counts.empty() ? "" : ", ") + std::to_string(list.samples) + " samples of " +
              std::to_string(list.variables.size()) + " signals on event '" + list.event->name + "'";
    if (list.incomplete != 0) counts += " and " + std::to_string(list.incomplete) + " incomplete";
  }
  return counts;
}

Result<mdf4_recording::DaqFile> create_mdf(const Session& session, const XcpOptions& options,
                                           const std::vector<RecordedList>& lists) {
  std::vector<mdf4_recording::DaqGroup> groups;
  for (const RecordedList& list : lists) {
    mdf4_recording::DaqGroup group{.event = *list.event, .variables = {}};
    for (const Variable* variable : list.variables) group.variables.push_back(*variable);
    groups.push_back(std::move(group));
  }
  const std::string comment = "duet xcp record: A2L " + options.a2l_file + " (module " + session.a2l->module +
                              "), slave " + xcp::host::to_string(session.slave);
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return mdf4_recording::DaqFile::create(options.mdf, std::move(groups), comment,
                                         std::chrono::duration_cast<std::chrono::nanoseconds>(now).count());
}

}  // namespace

ExitCode run_record(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true, streams.err);
  if (!session) return report({session.error()}, streams);
  if (!session.value().a2l) return report({"record needs --a2l FILE"}, streams);
  const A2lDescription& a2l = *session.value().a2l;
  Master& master = *session.value().master;
  auto recorded = recorded_lists(session.value(), options);
  if (!recorded) return report({recorded.error()}, streams);
  std::vector<RecordedList>& lists = recorded.value();
  // Times by the slave's timestamps, unless asked otherwise or there are none.
  const bool timestamped = !options.event_time && master.seconds_per_tick() > 0;
  std::vector<DaqListSetup> setups;
  plot::Figure figure{a2l.module + ", event " + event_names(lists), "s", {}, {}};
  for (const RecordedList& list : lists) {
    if (options.event_time && list.event->time_cycle == 0)
      return report({"--event-time: the A2L gives event '" + list.event->name + "' no period"}, streams);
    if (!options.event_time && !timestamped && list.event->time_cycle == 0) {
      return report({"the slave sends no timestamps and the A2L gives event '" + list.event->name +
                     "' no period: the samples cannot be timed"},
                    streams);
    }
    DaqListSetup setup{.event = list.event->channel, .prescaler = 1, .entries = {}};
    for (const Variable* found : list.variables) {
      for (std::uint32_t element = 0; element < found->count; ++element) {
        setup.entries.push_back({found->extension,
                                 found->address + element * static_cast<std::uint32_t>(size_of(found->type)),
                                 static_cast<std::uint8_t>(size_of(found->type))});
        figure.series.push_back(
            {found->name + (found->count > 1 ? "[" + std::to_string(element) + "]" : ""), found->unit, {}});
      }
    }
    setups.push_back(std::move(setup));
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
  std::optional<mdf4_recording::DaqFile> mdf;
  if (!options.mdf.empty()) {
    auto created = create_mdf(session.value(), options, lists);
    if (!created) return report({created.error()}, streams);
    mdf.emplace(std::move(created).value());
  }
  // A missing sample keeps its place in the MDF file and in the count --event-time times by.
  master.deliver_incomplete_samples(true);
  if (Status started = master.start_daq(setups); !started) return report({started.error()}, streams);
  std::ofstream no_csv;  // stays closed: with --mdf and no --output there is no CSV
  const bool csv_to_standard_output = options.output.empty() && options.mdf.empty();
  std::ostream& csv = csv_to_standard_output ? streams.out : options.output.empty() ? no_csv : file;
  const bool writing_csv = csv_to_standard_output || !options.output.empty();
  if (writing_csv) {
    csv << "time_s";
    for (const plot::Series& column : figure.series) csv << ',' << column.name;
    csv << '\n';
  }

  const double tick_seconds = master.seconds_per_tick();
  if (!options.event_time && !timestamped) {
    streams.err << "duet xcp: the slave sends no timestamps: the samples are timed by the events' periods\n";
  }
  const bool terminal = ::isatty(STDERR_FILENO) != 0 && &streams.err == &std::cerr;
  StopSignals stop;
  const auto start = std::chrono::steady_clock::now();
  const auto end = start + std::chrono::duration<double>(options.duration_s);
  auto next_flush = start + std::chrono::seconds{1};
  std::optional<std::int64_t> first_ticks;
  std::uint64_t samples = 0;
  double last_time_s = 0;
  std::size_t next_write = 0;
  std::optional<Failure> mdf_failure;
  std::vector<double> held(figure.series.size(), NAN);  // a plot's columns of the other events hold their last value
  bool stopped_by_signal = false;
  for (auto now = start; now < end; now = std::chrono::steady_clock::now()) {
    if (stop.received()) {
      stopped_by_signal = true;
      break;
    }
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
      RecordedList& list = lists.at(sample.list);
      if (!first_ticks) first_ticks = sample.ticks;
      const double time_s = timestamped ? static_cast<double>(sample.ticks - *first_ticks) * tick_seconds
                                        : static_cast<double>(list.samples + list.incomplete) * list.event->period_s();
      if (mdf && !mdf_failure) {
        Status appended =
            mdf->append(sample.list, time_s,
                        sample.complete ? std::optional{std::span<const std::uint8_t>{sample.bytes}} : std::nullopt);
        if (!appended) mdf_failure = Failure{appended.error()};
      }
      if (!sample.complete) {
        ++list.incomplete;
        continue;
      }
      last_time_s = time_s;
      if (writing_csv) csv << std::setprecision(9) << time_s;
      if (plotting) figure.time.push_back(time_s);
      std::size_t at = 0;
      std::size_t column = 0;
      for (const RecordedList& other : lists) {
        if (&other != &list) {
          if (writing_csv) csv << std::string(other.columns, ',');
          for (std::size_t k = 0; plotting && k < other.columns; ++k)
            figure.series[other.first_column + k].values.push_back(held[other.first_column + k]);
          continue;
        }
        column = list.first_column;
        for (const Variable* variable : list.variables) {
          const std::size_t bytes = size_of(variable->type) * variable->count;
          for (double value : decode(*variable, std::span{sample.bytes}.subspan(at, bytes))) {
            if (writing_csv) csv << ',' << std::setprecision(10) << value;
            if (plotting) {
              figure.series[column].values.push_back(value);
              held[column] = value;
            }
            ++column;
          }
          at += bytes;
        }
      }
      if (writing_csv) csv << '\n';
      ++list.samples;
      ++samples;
    }
    if (writing_csv && !csv) break;  // the disk is full or the reader went away: said below
    if (mdf_failure) break;
    if (mdf && now >= next_flush) {
      if (Status flushed = mdf->flush(); !flushed) {
        mdf_failure = Failure{flushed.error()};
        break;
      }
      next_flush = now + std::chrono::seconds{1};
    }
    if (terminal) {
      streams.err << "\rrecording " << std::fixed << std::setprecision(1) << elapsed << " / " << options.duration_s
                  << " s, " << samples << " samples" << std::flush;
    }
  }
  const Status stopped = master.stop_daq();
  const Status disconnected = master.disconnect();
  if (mdf && !mdf_failure) {
    if (Status finalised = mdf->finalise(); !finalised) mdf_failure = Failure{finalised.error()};
  }
  if (terminal) streams.err << '\n';
  if (stopped_by_signal) streams.err << "duet xcp: stopped by a signal; the files hold what came until then\n";
  const PacketCounters counters = master.counters();
  streams.err << "recorded " << sample_counts(lists) << " (" << packet_summary(counters) << ")\n";
  if (options.event_time && counters.lost() != 0) {
    streams.err << "duet xcp: samples were lost, so the times --event-time counted after the first loss are early\n";
  }
  if (plotting) {
    plot_file << plot::to_svg(figure);
    plot_file.close();
    if (!plot_file) return report({options.plot + ": cannot be written"}, streams);
  }
  if (writing_csv) csv.flush();
  if (writing_csv && !csv) {
    return report({(options.output.empty() ? std::string{"standard output"} : options.output) +
                   ": writing the samples failed after " + std::to_string(samples) + " of them"},
                  streams);
  }
  if (mdf_failure) return report(*mdf_failure, streams);
  if (!stopped) return report({stopped.error()}, streams);
  if (!disconnected) return report({disconnected.error()}, streams);
  for (const RecordedList& list : lists) {
    if (list.samples != 0 || stopped_by_signal) continue;
    std::ostringstream problem;
    problem << "no sample came in " << options.duration_s << " s: is event '" << list.event->name << "' running?";
    return report({problem.str()}, streams);
  }
  if (counters.lost() != 0) return report({"samples were lost (see the counts above)"}, streams);
  return ExitCode::success;
}

}  // namespace duet::cli::xcp_actions
