#include "daq_recorder.hpp"

#include <algorithm>

namespace duet::cli::xcp_actions {
namespace {

using namespace duet::xcp::host;

Result<const EventInfo*> event_named(const A2lDescription& a2l, const std::string& name) {
  for (const EventInfo& info : a2l.events) {
    if (info.name == name || std::to_string(info.channel) == name) return &info;
  }
  return Failure{"'" + name + "' is no event in the A2L (give its name or number)"};
}

}  // namespace

Result<std::vector<RecordedList>> recorded_lists(const Session& session, const std::vector<std::string>& signals,
                                                 const std::string& default_event) {
  if (!session.a2l) return Failure{"--signal needs --a2l FILE"};
  std::vector<RecordedList> lists;
  for (const std::string& text : signals) {
    const std::size_t at = text.rfind('@');
    const std::string event_name = at == std::string::npos ? default_event : text.substr(at + 1);
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

std::vector<mdf4_recording::DaqGroup> daq_groups(const std::vector<RecordedList>& lists) {
  std::vector<mdf4_recording::DaqGroup> groups;
  for (const RecordedList& list : lists) {
    mdf4_recording::DaqGroup group{.event = *list.event, .variables = {}};
    for (const Variable* variable : list.variables) group.variables.push_back(*variable);
    groups.push_back(std::move(group));
  }
  return groups;
}

std::string sample_counts(const std::vector<RecordedList>& lists) {
  std::string counts;
  for (const RecordedList& list : lists) {
    counts += (counts.empty() ? "" : ", ") + std::to_string(list.samples) + " samples of " +
              std::to_string(list.variables.size()) + " signals on event '" + list.event->name + "'";
    if (list.incomplete != 0) counts += " and " + std::to_string(list.incomplete) + " incomplete";
  }
  return counts;
}

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

DaqRecorder::DaqRecorder(Master& master, std::vector<RecordedList>& lists, DaqTime time)
    : master_(&master), lists_(&lists), time_(time), seconds_per_tick_(master.seconds_per_tick()) {}

Result<DaqRecorder> DaqRecorder::plan(Master& master, std::vector<RecordedList>& lists, DaqTime time) {
  const bool timestamped = master.seconds_per_tick() > 0;
  const bool periods_asked = time == DaqTime::event_periods;
  if (time == DaqTime::slave_clock && !timestamped) {
    return Failure{"the slave sends no DAQ timestamps: its samples cannot be put on its clock"};
  }
  if (time == DaqTime::since_first_sample && !timestamped) time = DaqTime::event_periods;
  for (const RecordedList& list : lists) {
    if (time != DaqTime::event_periods || list.event->time_cycle != 0) continue;
    if (periods_asked) return Failure{"--event-time: the A2L gives event '" + list.event->name + "' no period"};
    return Failure{"the slave sends no timestamps and the A2L gives event '" + list.event->name +
                   "' no period: the samples cannot be timed"};
  }
  return DaqRecorder{master, lists, time};
}

Status DaqRecorder::start() {
  std::vector<DaqListSetup> setups;
  for (const RecordedList& list : *lists_) {
    DaqListSetup setup{.event = list.event->channel, .prescaler = 1, .entries = {}};
    for (const Variable* found : list.variables) {
      for (std::uint32_t element = 0; element < found->count; ++element) {
        setup.entries.push_back({found->extension,
                                 found->address + element * static_cast<std::uint32_t>(size_of(found->type)),
                                 static_cast<std::uint8_t>(size_of(found->type))});
      }
    }
    setups.push_back(std::move(setup));
  }
  // A missing sample keeps its place in an MDF file and in the count event_periods times by.
  master_->deliver_incomplete_samples(true);
  return master_->start_daq(setups);
}

Status DaqRecorder::receive(std::chrono::milliseconds wait, const Take& take) {
  auto received = master_->receive_samples(wait);
  if (!received) return Failure{received.error()};
  for (const DaqSample& sample : received.value()) {
    RecordedList& list = lists_->at(sample.list);
    if (!first_ticks_) first_ticks_ = sample.ticks;
    double time_s = 0;
    switch (time_) {
      case DaqTime::since_first_sample:
        time_s = static_cast<double>(sample.ticks - *first_ticks_) * seconds_per_tick_;
        break;
      case DaqTime::slave_clock: time_s = static_cast<double>(sample.ticks) * seconds_per_tick_; break;
      case DaqTime::event_periods:
        time_s = static_cast<double>(list.samples + list.incomplete) * list.event->period_s();
        break;
    }
    take(list, time_s, sample);
    if (!sample.complete) {
      ++list.incomplete;
      continue;
    }
    last_time_s_ = time_s;
    ++list.samples;
    ++samples_;
  }
  return done();
}

}  // namespace duet::cli::xcp_actions
