#pragma once
// `duet pil --signal`: the firmware's signals, recorded over XCP through the run's bridge by a master in a thread of
// duet pil's own, into the run's MDF file beside the plant's truth (mdf4_recording::PlantAndDaqFile). The samples
// are timed by the firmware's DAQ timestamps from its clock's zero: the simulation time the plant's rows have too.

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <thread>
#include <vector>

#include "daq_recorder.hpp"
#include "duet/mdf4_recording/plant_and_daq_file.hpp"

namespace duet::cli {

struct FirmwareSignals {
  std::string a2l_file;
  std::vector<std::string> signals;  // NAME[@EVENT]
  std::string event;                 // for a NAME without @EVENT
};

class FirmwareRecording {
 public:
  // Reads the A2L and checks the signals and their events, before the run starts; the A2L's warnings go to
  // `warnings`.
  static Result<std::unique_ptr<FirmwareRecording>> prepare(const FirmwareSignals& wanted, std::ostream& warnings);
  FirmwareRecording(const FirmwareRecording&) = delete;
  FirmwareRecording& operator=(const FirmwareRecording&) = delete;
  ~FirmwareRecording();  // stops the thread if stop() was not called

  // The DAQ lists as the file's groups, after the plant's.
  [[nodiscard]] std::vector<mdf4_recording::DaqGroup> groups() const;
  // Starts the thread: connects to the bridge at `xcp` (HOST:PORT), again and again until the firmware answers
  // (within answer_within), starts DAQ and appends every sample to `file` until stop().
  void start(const std::string& xcp, mdf4_recording::PlantAndDaqFile& file);
  // Whether the thread gave up (the firmware did not answer, DAQ failed): the run should end.
  [[nodiscard]] bool failed() const { return failed_; }
  // Ends the recording and joins the thread: DAQ stopped and the master disconnected when `firmware_runs` (else the
  // firmware cannot answer). The first failure, if any.
  Status stop(bool firmware_runs);
  // "recorded 9000 samples of 1 signals on event 'rate 1', ... (0 overloads, 0 lost packets, 0 discarded)".
  [[nodiscard]] std::string summary() const;

  static constexpr std::chrono::seconds answer_within{30};
  static constexpr std::chrono::milliseconds command_timeout{2000};

 private:
  FirmwareRecording() = default;
  void record(std::string xcp, mdf4_recording::PlantAndDaqFile& file);
  Status connect(const std::string& xcp);
  Status sample(mdf4_recording::PlantAndDaqFile& file);

  xcp_actions::Session session_;  // its A2L, and the master once connected
  std::vector<xcp_actions::RecordedList> lists_;
  std::thread thread_;
  std::atomic<bool> stopping_{false};
  std::atomic<bool> firmware_runs_{true};  // at the stop
  std::atomic<bool> failed_{false};
  std::optional<Failure> failure_;  // written by the thread, read once it is joined
};

}  // namespace duet::cli
