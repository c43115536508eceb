#pragma once
// What `duet xcp record` and `duet pil --signal` share: the DAQ lists of --signal NAME[@EVENT] options, a list per
// event, set up on the slave, and their samples as they come, timed and counted; the summary line of what came.

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "duet/mdf4_recording/daq_file.hpp"
#include "xcp_session.hpp"

namespace duet::cli::xcp_actions {

// One DAQ list: an event and the signals it samples, and where their columns start in a CSV or a plot.
struct RecordedList {
  const xcp::host::EventInfo* event = nullptr;
  std::vector<const xcp::host::Variable*> variables;
  std::size_t first_column = 0;
  std::size_t columns = 0;
  std::uint64_t samples = 0;     // complete ones
  std::uint64_t incomplete = 0;  // reported by the master, timed but without values
};

// The lists of `signals` (NAME@EVENT, or NAME on `default_event`), a list per event in the order first named; the
// names are checked against the session's A2L.
[[nodiscard]] Result<std::vector<RecordedList>> recorded_lists(const Session& session,
                                                               const std::vector<std::string>& signals,
                                                               const std::string& default_event);
// The lists as an MDF file's groups (mdf4_recording::DaqFile).
[[nodiscard]] std::vector<mdf4_recording::DaqGroup> daq_groups(const std::vector<RecordedList>& lists);
// "42 samples of 2 signals on event 'rate 1', ..." (and the incomplete ones).
[[nodiscard]] std::string sample_counts(const std::vector<RecordedList>& lists);
// What became of the packets: "2 overloads, 0 lost packets, 3 discarded: 1 of unknown ODTs, ...".
[[nodiscard]] std::string packet_summary(const xcp::host::PacketCounters& counters);

// How a sample's time in seconds is found.
enum class DaqTime : std::uint8_t {
  since_first_sample,  // the slave's timestamp, from the first sample of any list
  slave_clock,         // the slave's timestamp as it is (its clock's zero)
  event_periods,       // the sample's number times its event's period
};

// Samples the lists on a connected master and hands each sample over, timed; counts them in the lists.
class DaqRecorder {
 public:
  using Take = std::function<void(RecordedList& list, double time_s, const xcp::host::DaqSample& sample)>;

  // Checks that every sample can be timed as asked: by the slave's timestamps, or by the A2L's periods when the slave
  // sends none (since_first_sample) or when asked (event_periods).
  static Result<DaqRecorder> plan(xcp::host::Master& master, std::vector<RecordedList>& lists, DaqTime time);
  // Sets the lists up on the slave and starts them. Incomplete samples are delivered too (DaqSample::complete false).
  Status start();

  // Waits up to `wait` for samples and hands each to `take`; counted after it.
  Status receive(std::chrono::milliseconds wait, const Take& take);
  [[nodiscard]] DaqTime time() const { return time_; }
  [[nodiscard]] std::uint64_t samples() const { return samples_; }
  [[nodiscard]] double last_time_s() const { return last_time_s_; }  // of the last complete sample

 private:
  DaqRecorder(xcp::host::Master& master, std::vector<RecordedList>& lists, DaqTime time);
  xcp::host::Master* master_;
  std::vector<RecordedList>* lists_;
  DaqTime time_;
  double seconds_per_tick_;
  std::optional<std::int64_t> first_ticks_;
  std::uint64_t samples_ = 0;
  double last_time_s_ = 0;
};

}  // namespace duet::cli::xcp_actions
