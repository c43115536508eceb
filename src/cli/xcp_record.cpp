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

#include "daq_recorder.hpp"
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

std::string event_names(const std::vector<RecordedList>& lists) {
  std::string names;
  for (const RecordedList& list : lists) names += (names.empty() ? "'" : ", '") + list.event->name + "'";
  return names;
}

Result<mdf4_recording::DaqFile> create_mdf(const Session& session, const XcpOptions& options,
                                           const std::vector<RecordedList>& lists) {
  const std::string comment = "duet xcp record: A2L " + options.a2l_file + " (module " + session.a2l->module +
                              "), slave " + xcp::host::to_string(session.slave);
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return mdf4_recording::DaqFile::create(options.mdf, daq_groups(lists), comment,
                                         std::chrono::duration_cast<std::chrono::nanoseconds>(now).count());
}

}  // namespace

ExitCode run_record(const XcpOptions& options, Streams streams) {
  auto session = open_session(options, true, streams.err);
  if (!session) return report({session.error()}, streams);
  if (!session.value().a2l) return report({"record needs --a2l FILE"}, streams);
  const A2lDescription& a2l = *session.value().a2l;
  Master& master = *session.value().master;
  auto recorded = recorded_lists(session.value(), options.signals, options.event);
  if (!recorded) return report({recorded.error()}, streams);
  std::vector<RecordedList>& lists = recorded.value();
  // Times by the slave's timestamps, unless asked otherwise or there are none.
  auto planned =
      DaqRecorder::plan(master, lists, options.event_time ? DaqTime::event_periods : DaqTime::since_first_sample);
  if (!planned) return report({planned.error()}, streams);
  DaqRecorder& recorder = planned.value();
  plot::Figure figure{a2l.module + ", event " + event_names(lists), "s", {}, {}};
  for (const RecordedList& list : lists) {
    for (const Variable* found : list.variables) {
      for (std::uint32_t element = 0; element < found->count; ++element) {
        figure.series.push_back(
            {found->name + (found->count > 1 ? "[" + std::to_string(element) + "]" : ""), found->unit, {}});
      }
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
  std::optional<mdf4_recording::DaqFile> mdf;
  if (!options.mdf.empty()) {
    auto created = create_mdf(session.value(), options, lists);
    if (!created) return report({created.error()}, streams);
    mdf.emplace(std::move(created).value());
  }
  if (Status started = recorder.start(); !started) return report({started.error()}, streams);
  std::ofstream no_csv;  // stays closed: with --mdf and no --output there is no CSV
  const bool csv_to_standard_output = options.output.empty() && options.mdf.empty();
  std::ostream& csv = csv_to_standard_output ? streams.out : options.output.empty() ? no_csv : file;
  const bool writing_csv = csv_to_standard_output || !options.output.empty();
  if (writing_csv) {
    csv << "time_s";
    for (const plot::Series& column : figure.series) csv << ',' << column.name;
    csv << '\n';
  }

  if (!options.event_time && recorder.time() == DaqTime::event_periods) {
    streams.err << "duet xcp: the slave sends no timestamps: the samples are timed by the events' periods\n";
  }
  const bool terminal = ::isatty(STDERR_FILENO) != 0 && &streams.err == &std::cerr;
  StopSignals stop;
  const auto start = std::chrono::steady_clock::now();
  const auto end = start + std::chrono::duration<double>(options.duration_s);
  auto next_flush = start + std::chrono::seconds{1};
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
      if (recorder.samples() != 0)
        streams.err << " (the last sample so far at " << std::setprecision(3) << recorder.last_time_s() << " s)";
      streams.err << '\n';
    }
    auto wait = std::chrono::milliseconds{50};
    if (next_write < writes.value().size()) {
      const auto until_write = std::chrono::duration<double>(writes.value()[next_write].at_s - elapsed);
      wait = std::min(wait, std::chrono::ceil<std::chrono::milliseconds>(until_write));
    }
    const Status received = recorder.receive(wait, [&](RecordedList& list, double time_s, const DaqSample& sample) {
      if (mdf && !mdf_failure) {
        Status appended =
            mdf->append(sample.list, time_s,
                        sample.complete ? std::optional{std::span<const std::uint8_t>{sample.bytes}} : std::nullopt);
        if (!appended) mdf_failure = Failure{appended.error()};
      }
      if (!sample.complete) return;
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
    });
    if (!received) return report({received.error()}, streams);
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
                  << " s, " << recorder.samples() << " samples" << std::flush;
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
                   ": writing the samples failed after " + std::to_string(recorder.samples()) + " of them"},
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
