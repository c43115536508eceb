#include "pil_firmware_recording.hpp"

#include <span>

namespace duet::cli {

using namespace std::chrono_literals;
using xcp_actions::DaqRecorder;
using xcp_actions::RecordedList;

Result<std::unique_ptr<FirmwareRecording>> FirmwareRecording::prepare(const FirmwareSignals& wanted,
                                                                      std::ostream& warnings) {
  xcp_actions::XcpOptions reading;
  reading.a2l_file = wanted.a2l_file;
  auto session = xcp_actions::open_session(reading, false, warnings);
  if (!session) return Failure{session.error()};
  std::unique_ptr<FirmwareRecording> recording{new FirmwareRecording};
  recording->session_ = std::move(session).value();
  // The lists point into the session's A2L, which stays where it is from now on.
  auto lists = xcp_actions::recorded_lists(recording->session_, wanted.signals, wanted.event);
  if (!lists) return Failure{lists.error()};
  recording->lists_ = std::move(lists).value();
  return recording;
}

FirmwareRecording::~FirmwareRecording() {
  if (thread_.joinable()) (void)stop(false);
}

std::vector<mdf4_recording::DaqGroup> FirmwareRecording::groups() const { return xcp_actions::daq_groups(lists_); }

void FirmwareRecording::start(const std::string& xcp, mdf4_recording::PlantAndDaqFile& file) {
  thread_ = std::thread{[this, xcp, &file] { record(xcp, file); }};
}

Status FirmwareRecording::stop(bool firmware_runs) {
  firmware_runs_ = firmware_runs;
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
  if (failure_) return *failure_;
  return done();
}

std::string FirmwareRecording::summary() const {
  std::string text = "recorded " + xcp_actions::sample_counts(lists_);
  if (session_.master) text += " (" + xcp_actions::packet_summary(session_.master->counters()) + ")";
  return text;
}

void FirmwareRecording::record(std::string xcp, mdf4_recording::PlantAndDaqFile& file) {
  Status recorded = connect(xcp);
  if (recorded) recorded = sample(file);
  if (!recorded) {
    failure_ = Failure{recorded.error()};
    failed_ = true;
  }
}

// The firmware answers once it runs its XCP slave, and the bridge once it reached QEMU's UART: until then a CONNECT
// goes unanswered, and is tried again on a new connection.
Status FirmwareRecording::connect(const std::string& xcp) {
  auto endpoint = xcp::host::parse_endpoint("tcp://" + xcp);
  if (!endpoint) return Failure{endpoint.error()};
  const auto deadline = std::chrono::steady_clock::now() + answer_within;
  std::string last_problem;
  while (!stopping_) {
    const Status connected = xcp_actions::connect_master(session_, endpoint.value(), command_timeout);
    if (connected) return done();
    last_problem = connected.error();
    session_.master.reset();
    if (std::chrono::steady_clock::now() >= deadline) {
      return Failure{"the firmware did not answer XCP on tcp://" + xcp + " within " +
                     std::to_string(answer_within.count()) + " s: " + last_problem};
    }
    std::this_thread::sleep_for(100ms);
  }
  return Failure{"the run ended before the firmware answered XCP on tcp://" + xcp +
                 (last_problem.empty() ? std::string{} : " (" + last_problem + ")")};
}

Status FirmwareRecording::sample(mdf4_recording::PlantAndDaqFile& file) {
  xcp::host::Master& master = *session_.master;
  auto planned = DaqRecorder::plan(master, lists_, xcp_actions::DaqTime::slave_clock);
  if (!planned) return Failure{"the firmware's DAQ: " + planned.error()};
  DaqRecorder& recorder = planned.value();
  if (Status started = recorder.start(); !started) return Failure{"the firmware's DAQ: " + started.error()};
  const DaqRecorder::Take append = [&file](RecordedList&, double time_s, const xcp::host::DaqSample& sample) {
    file.append_daq(sample.list, time_s,
                    sample.complete ? std::optional{std::span<const std::uint8_t>{sample.bytes}} : std::nullopt);
  };
  while (!stopping_) {
    if (Status received = recorder.receive(50ms, append); !received) {
      return Failure{"the firmware's DAQ: " + received.error()};
    }
  }
  if (!firmware_runs_) return done();
  if (Status stopped = master.stop_daq(); !stopped) return Failure{"the firmware's DAQ: " + stopped.error()};
  return master.disconnect();
}

}  // namespace duet::cli
