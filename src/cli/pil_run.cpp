#include "pil_run.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <span>
#include <string_view>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "duet/link/named_pipes.hpp"
#include "duet/support/temporary_folder.hpp"
#include "firmware_console.hpp"
#include "machine_load.hpp"
#include "pil_programs.hpp"
#include "pil_summary.hpp"
#include "plant_control_endpoint.hpp"
#include "plant_session.hpp"
#include "stop_signals.hpp"

namespace duet::cli {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

constexpr std::string_view prefix = "duet pil: ";
constexpr auto console_gathering = 10ms;

// Bytes from a pipe, cut into lines (a line too long to be one is cut too).
class LineSplitter {
 public:
  // Reads what `fd` has without blocking and returns the complete lines; at the pipe's end, the last bit too.
  std::vector<std::string> read(int fd) {
    std::vector<std::string> lines;
    char bytes[4096];
    for (;;) {
      const ssize_t got = ::read(fd, bytes, sizeof bytes);
      if (got <= 0) {
        if (got == 0) ended_ = true;
        if (got == 0 && !pending_.empty()) {
          lines.push_back(std::exchange(pending_, {}));
          ended_mid_line_ = true;
        }
        return lines;
      }
      for (const char byte : std::string_view{bytes, static_cast<std::size_t>(got)}) {
        if (byte == '\n' || pending_.size() == longest_line) {
          lines.push_back(std::exchange(pending_, {}));
          if (byte == '\n') continue;
        }
        pending_ += byte;
      }
    }
  }
  // Whether the pipe has ended (polling it further would only say so again and again).
  [[nodiscard]] bool ended() const { return ended_; }
  // Whether the last line read had no end: the writer stopped in the middle of it.
  [[nodiscard]] bool ended_mid_line() const { return ended_mid_line_; }

 private:
  static constexpr std::size_t longest_line = 4096;
  std::string pending_;
  bool ended_ = false;
  bool ended_mid_line_ = false;
};

void make_non_blocking(int fd) {
  if (fd >= 0) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
}

// The bridge's first lines, up to the two that say where it listens (its port 0 becomes a real port there), so that
// a run does not start before its bridge can be reached, and a short one does not stop the bridge before it can
// report its counters. Empty addresses: it ended first or did not say within 10 s.
struct BridgeStart {
  LineSplitter lines;
  std::string output;
  std::string xcp;        // HOST:PORT
  std::string websocket;  // HOST:PORT
};

BridgeStart wait_until_listening(ChildProcess& bridge) {
  BridgeStart start;
  make_non_blocking(bridge.errors_fd());
  const auto address_after = [](const std::string& line, std::string_view label) {
    const std::size_t at = line.find(label);
    if (at == std::string::npos) return std::string{};
    const std::size_t begin = at + label.size();
    return line.substr(begin, line.find(' ', begin) - begin);
  };
  const auto deadline = Clock::now() + 10s;
  while ((start.xcp.empty() || start.websocket.empty()) && !start.lines.ended() && Clock::now() < deadline) {
    pollfd watched{bridge.errors_fd(), POLLIN, 0};
    ::poll(&watched, 1, 100);
    for (const std::string& line : start.lines.read(bridge.errors_fd())) {
      start.output += line + '\n';
      if (start.xcp.empty()) start.xcp = address_after(line, "listening for an XCP master on ");
      if (start.websocket.empty()) start.websocket = address_after(line, "WebSocket clients on ");
    }
  }
  return start;
}

// Why watching the run ended.
enum class Ending : std::uint8_t { signal, qemu_exited, plant_failed, qemu_lingered, bridge_exited, recording_failed };

// Watches the children and the plant session, handling their output, until something ends the run; then stops
// everything in order.
class Supervisor {
 public:
  // `bridge_start`: what the bridge said before the run began (wait_until_listening).
  Supervisor(Streams streams, std::ofstream& console, ChildProcess& qemu, ChildProcess* bridge, PlantSession& session,
             BridgeStart bridge_start)
      : streams_(streams),
        console_(console),
        qemu_(qemu),
        bridge_(bridge),
        session_(session),
        bridge_errors_(std::move(bridge_start.lines)),
        bridge_output_(std::move(bridge_start.output)) {
    make_non_blocking(qemu_.output_fd());
    make_non_blocking(qemu_.errors_fd());
  }

  // `recording`: the firmware's signals' (--signal), whose failure ends the run too; may be null.
  Ending watch(StopSignals& signals, const FirmwareRecording* recording) {
    std::optional<Clock::time_point> plant_finished;
    for (;;) {
      const auto unless_ended = [](int fd, const LineSplitter& lines) { return lines.ended() ? -1 : fd; };
      std::vector<pollfd> watched{{signals.fd(), POLLIN, 0},
                                  {unless_ended(qemu_.output_fd(), console_lines_), POLLIN, 0},
                                  {unless_ended(qemu_.errors_fd(), qemu_errors_), POLLIN, 0}};
      if (bridge_ != nullptr) watched.push_back({unless_ended(bridge_->errors_fd(), bridge_errors_), POLLIN, 0});
      ::poll(watched.data(), watched.size(), 100);  // also the pace at which exits are noticed
      // QEMU writes the console a byte per system call: read as they come, a second's report (some 1,700 bytes)
      // would wake this thread as many times, each wake-up taking a processor from QEMU and the plant in the tick
      // that prints it. Let them gather a little.
      std::this_thread::sleep_for(console_gathering);
      pump();
      if (signals.received()) return Ending::signal;
      if (qemu_.exit_code()) return Ending::qemu_exited;
      if (bridge_ != nullptr && bridge_->exit_code()) return Ending::bridge_exited;
      if (recording != nullptr && recording->failed()) return Ending::recording_failed;
      if (session_.finished()) {
        // The emulator usually ends with the session (the firmware said BYE, or it died mid-tick): give it a
        // moment to end by itself and say how (its exit code), then stop it.
        if (!plant_finished) plant_finished = Clock::now();
        const bool served_well = session_.served_well();
        if (Clock::now() - *plant_finished > (served_well ? 5s : 1s)) {
          return served_well ? Ending::qemu_lingered : Ending::plant_failed;
        }
      }
    }
  }

  // QEMU first (its end ends the plant session), then the bridge, which prints its counters on SIGINT.
  void stop_children() {
    stopping_ = true;
    qemu_exit_code_ = qemu_.stop(2s);
    if (bridge_ != nullptr) bridge_exit_code_ = bridge_->stop(2s, SIGINT);
    pump();
  }

  // Reads every pipe that has something, handling complete lines.
  void pump() {
    std::vector<std::string> lines = console_lines_.read(qemu_.output_fd());
    // The stop we asked for may cut the firmware's last line: kept in the console file, not read as a report.
    const bool cut_by_the_stop = stopping_ && console_lines_.ended_mid_line() && !lines.empty();
    for (std::size_t k = 0; k < lines.size(); ++k) {
      if (cut_by_the_stop && k + 1 == lines.size()) {
        if (console_.is_open()) console_ << lines[k] << std::endl;
      } else {
        on_console(std::move(lines[k]));
      }
    }
    for (const std::string& line : qemu_errors_.read(qemu_.errors_fd())) {
      // QEMU's "terminating on signal 15" is the stop we asked for, not news.
      if (!(stopping_ && line.find("terminating on signal") != std::string::npos)) streams_.err << line << '\n';
    }
    if (bridge_ != nullptr) {
      for (const std::string& line : bridge_errors_.read(bridge_->errors_fd())) bridge_output_ += line + '\n';
    }
    streams_.err.flush();
  }

  [[nodiscard]] const FirmwareReport& report() const { return report_; }
  [[nodiscard]] const std::string& bridge_output() const { return bridge_output_; }
  [[nodiscard]] int qemu_exit_code() const { return qemu_exit_code_; }
  [[nodiscard]] int bridge_exit_code() const { return bridge_exit_code_; }

 private:
  void on_console(std::string line) {
    if (line.ends_with('\r')) line.pop_back();
    if (console_.is_open()) console_ << line << std::endl;  // flushed: the file can be followed (tail -f)
    const ConsoleLine parsed = parse_console_line(line);
    if (const auto* malformed = std::get_if<MalformedLine>(&parsed)) {
      streams_.err << prefix << "the firmware's console: " << malformed->problem << " in '" << line << "'\n";
    } else if (const auto* text = std::get_if<ConsoleText>(&parsed);
               text != nullptr && text->text.starts_with("error")) {
      streams_.err << prefix << "the firmware says: " << text->text << '\n';
    }
    take(report_, parsed);
  }

  Streams streams_;
  std::ofstream& console_;
  ChildProcess& qemu_;
  ChildProcess* bridge_;
  PlantSession& session_;
  LineSplitter console_lines_;
  LineSplitter qemu_errors_;
  LineSplitter bridge_errors_;
  FirmwareReport report_;
  std::string bridge_output_;
  bool stopping_ = false;
  int qemu_exit_code_ = 0;
  int bridge_exit_code_ = 0;
};

void print_how_to_connect(const PilOptions& options, const std::filesystem::path& folder,
                          const PlantControlEndpoint& control, std::ostream& out) {
  out << "duet pil: " << std::filesystem::path{options.firmware}.filename().string()
      << " on QEMU mps2-an386 (-icount shift=" << options.icount_shift << "), plant " << options.plant.name
      << (options.lock_step ? ", lock-step\n" : ", real time\n");
  if (options.bridge) {
    out << "  XCP        tcp://" << options.xcp;
    if (options.plant.name == "balbot") out << " (A2L: apps/balbot/generated/balbot.a2l)";
    out << ", e.g. duet xcp info --connect tcp://" << options.xcp << '\n';
    out << "  dashboard  http://" << options.websocket
        << "/ (the bridge's: the application channel; its JSON API on the same port, docs/DASHBOARD.md)\n";
    if (options.plant.name == "balbot") {
      out << "  monitor    duet monitor --xcp tcp://" << options.xcp << " --a2l apps/balbot/generated/balbot.a2l";
      if (!control.address().empty()) out << " --plant-control " << control.address();
      out << " (the dashboard over XCP)\n";
    }
  } else {
    out << "  XCP        no bridge (--no-bridge): the firmware's XCP channel is unix:" << (folder / "xcp.sock").string()
        << ", its application channel unix:" << (folder / "app.sock").string() << '\n';
  }
  if (!control.address().empty()) {
    out << "  plant      " << control.actions() << " from the dashboards (Tuning page, Disturb), or JSON lines on "
        << control.address() << " (docs/LINK.md)\n";
  }
  out << "  Ctrl-C ends the run";
  if (options.duration_s) out << " (else it ends after " << shortest(*options.duration_s) << " s of model time)";
  out << std::endl;  // before the run's own output
}

// Whether the run went well, from how it ended; failures are said on `err`.
bool judge(Ending ending, const Supervisor& supervisor, const PlantSession::Outcome& session, bool session_ended_first,
           std::ostream& out, std::ostream& err) {
  const FirmwareReport& report = supervisor.report();
  const auto plant_failure = [&] {
    err << prefix << "the plant session failed: " << session.served.error() << '\n';
    return false;
  };
  switch (ending) {
    case Ending::signal:
      out << "duet pil: stopped by a signal\n";
      // A session cut by the stop is no failure; one that had failed before is.
      if (session_ended_first && !session.served) return plant_failure();
      return true;
    case Ending::qemu_exited: {
      const int code = supervisor.qemu_exit_code();
      if (!session.connected) {
        out << "duet pil: QEMU ended with exit code " << code << '\n';
        err << prefix << "QEMU ended with exit code " << code << " before the firmware connected to the plant\n";
        return false;
      }
      out << "duet pil: the firmware ended" << (report.end ? " (" + report.end->reason + ")" : std::string{})
          << " with exit code " << code << '\n';
      // The plant ended the run (an FMU asked to stop); the firmware learnt of it as a link error.
      if (!session.summary.plant_stop.empty()) {
        out << "duet pil: " << session.summary.plant_stop << '\n';
        return true;
      }
      if (code != 0) {
        err << prefix << "the firmware failed: exit code " << code << '\n';
        return false;
      }
      return session.served.ok() || plant_failure();
    }
    case Ending::plant_failed: return plant_failure();
    case Ending::qemu_lingered:
      err << prefix << "the firmware ended its plant session, but QEMU did not exit within 5 s\n";
      return false;
    case Ending::bridge_exited:
      err << prefix << "duet-bridge ended by itself (exit code " << supervisor.bridge_exit_code()
          << "); what it said:\n"
          << supervisor.bridge_output();
      return false;
    case Ending::recording_failed: return false;  // the recording's failure is said with its file
  }
  return false;
}

// What the summary says, from what the run left behind.
PilRun summarise(const PilOptions& options, const ChosenPlant& chosen, const RecordingPlant& plant,
                 const PlantControlEndpoint& control, const Supervisor& supervisor,
                 const PlantSession::Outcome& outcome, double run_wall_s) {
  PilRun run{.lock_step = options.lock_step,
             .icount_shift = options.icount_shift,
             .wall_s = outcome.connected ? outcome.wall_time.count() : run_wall_s,
             .firmware = supervisor.report(),
             .bridge = options.bridge};
  if (outcome.connected) run.session = outcome.summary;
  // How far the run went: the session's last tick, or without a session what the firmware last said.
  if (run.session) {
    run.model_time_s = run.session->last_tick_s;
  } else if (run.firmware.status) {
    run.model_time_s = run.firmware.status->time_s;
  }
  run.tilt = tilt_statistics(plant.recording(), 0);
  const std::optional<plant::BalbotScenario>& scenario = chosen.scenario;
  if (scenario && scenario->rig == plant::BalbotRig::on_ground && scenario->release_time_s > 0) {
    run.tilt_after_release = tilt_statistics(plant.recording(), scenario->release_time_s);
  }
  run.recording_truncated = plant.truncated();
  run.disturbances = control.applied();
  run.offered = control.offered();
  if (options.bridge) run.xcp = parse_bridge_counters(supervisor.bridge_output());
  return run;
}

// The run's MDF file (--mdf): the plant's rows and the firmware's DAQ samples streamed into it as they come.
Result<std::unique_ptr<mdf4_recording::PlantAndDaqFile>> create_mdf(const PilOptions& options,
                                                                    const model::Recording& plant,
                                                                    const FirmwareRecording* firmware) {
  std::string comment = "duet pil: plant " + options.plant.name + " under " + options.firmware;
  if (firmware != nullptr) comment += ", its signals by XCP (A2L " + options.firmware_signals.a2l_file + ")";
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return mdf4_recording::PlantAndDaqFile::create(
      options.recording.mdf, {.names = plant.names, .units = plant.units},
      firmware != nullptr ? firmware->groups() : std::vector<mdf4_recording::DaqGroup>{}, comment,
      std::chrono::duration_cast<std::chrono::nanoseconds>(now).count());
}

}  // namespace

ExitCode run_pil(const PilOptions& options, Streams streams) {
  const auto fail = [&streams](const std::string& message) {
    streams.err << prefix << message << '\n';
    return ExitCode::failure;
  };
  auto chosen = choose_plant(options.plant, log_lines_to(streams.err));
  if (!chosen) return fail(chosen.error());
  std::unique_ptr<FirmwareRecording> firmware_recording;
  if (!options.firmware_signals.signals.empty()) {
    auto prepared = FirmwareRecording::prepare(options.firmware_signals, streams.err);
    if (!prepared) return fail(prepared.error());
    firmware_recording = std::move(prepared).value();
  }
  if (Status created = create_recording_files(options.recording); !created) return fail(created.error());
  std::ofstream console;
  if (!options.console.empty()) {
    console.open(options.console);
    if (!console) return fail("cannot write " + options.console);
  }
  auto folder = TemporaryFolder::make("duet-pil-");
  if (!folder) return fail(folder.error());
  auto pipes = link::NamedPipes::create(folder.value().path());
  if (!pipes) return fail("the plant: " + pipes.error());
  auto control = PlantControlEndpoint::open(chosen.value(), options.plant.name, options.plant_control);
  if (!control) return fail(control.error());
  std::unique_ptr<mdf4_recording::PlantAndDaqFile> mdf;  // made before the session, which streams into it
  auto made = chosen.value().make();
  if (!made) return fail(made.error());
  RecordingPlant plant{control.value().controlled(std::move(made).value()), true,  // always: the summary's tilt
                       [&mdf](double time_s, std::span<const double> row) {
                         if (mdf) mdf->append_plant(time_s, row);
                       }};
  if (!options.recording.mdf.empty()) {
    auto created = create_mdf(options, plant.recording(), firmware_recording.get());
    if (!created) return fail(created.error());
    mdf = std::move(created).value();
  }
  StopSignals signals;
  const QemuSetup qemu_setup{options.qemu, options.firmware, options.icount_shift, options.duration_s,
                             folder.value().path()};
  auto qemu = ChildProcess::start(qemu_command(qemu_setup), {ChildProcess::Output::pipe, ChildProcess::Output::pipe});
  if (!qemu) return fail(qemu.error() + " (Debian: apt install qemu-system-arm; or give --qemu PATH)");
  std::optional<ChildProcess> bridge;
  if (options.bridge) {
    std::error_code no_link;  // then the bridge is looked up on PATH
    const std::string program = options.bridge_program.empty()
                                    ? default_bridge(std::filesystem::read_symlink("/proc/self/exe", no_link))
                                    : options.bridge_program;
    auto started = ChildProcess::start(
        bridge_command({program, folder.value().path(), options.xcp, options.websocket, control.value().address()}),
        {ChildProcess::Output::discard, ChildProcess::Output::pipe});
    if (!started) return fail(started.error() + " (build the target duet-bridge, give --bridge PATH, or --no-bridge)");
    bridge.emplace(std::move(started).value());
  }
  BridgeStart bridge_start;
  PilOptions listening = options;  // with the ports the bridge took
  if (bridge) {
    bridge_start = wait_until_listening(*bridge);
    if (bridge_start.xcp.empty() || bridge_start.websocket.empty()) {
      return fail("duet-bridge did not start listening:\n" + bridge_start.output);
    }
    listening.xcp = bridge_start.xcp;
    listening.websocket = bridge_start.websocket;
  }
  const Clock::time_point start = Clock::now();
  const MachineLoadMeter machine_load;
  PlantSession session{std::move(pipes).value(), plant, {.paced = !options.lock_step}, 10s};
  print_how_to_connect(listening, folder.value().path(), control.value(), streams.out);
  if (firmware_recording) firmware_recording->start(listening.xcp, *mdf);

  Supervisor supervisor{streams, console, qemu.value(), bridge ? &*bridge : nullptr, session, std::move(bridge_start)};
  const Ending ending = supervisor.watch(signals, firmware_recording.get());
  const bool session_ended_first = session.finished();
  // Before the children stop: after a signal the firmware still runs, and DAQ is stopped on it.
  Status firmware_recorded = done();
  if (firmware_recording) firmware_recorded = firmware_recording->stop(ending == Ending::signal);
  supervisor.stop_children();
  session.cancel();
  const PlantSession::Outcome outcome = session.join();
  const double run_wall_s = std::chrono::duration<double>(Clock::now() - start).count();

  const bool went_well = judge(ending, supervisor, outcome, session_ended_first, streams.out, streams.err);
  PilRun run = summarise(options, chosen.value(), plant, control.value(), supervisor, outcome, run_wall_s);
  run.machine = machine_load.finish(run_wall_s);
  if (firmware_recording) run.daq = firmware_recording->summary();
  streams.out << format_summary(run) << std::flush;

  if (!firmware_recorded)
    streams.err << prefix << "recording the firmware's signals: " << firmware_recorded.error() << '\n';
  Status mdf_written = done();
  if (mdf) mdf_written = mdf->finalise();
  if (!mdf_written) streams.err << prefix << mdf_written.error() << '\n';
  RecordingFiles at_the_end = options.recording;
  at_the_end.mdf.clear();  // streamed
  const Status written = write_recording_files(plant.recording(), at_the_end,
                                               "plant " + options.plant.name + " under " + options.firmware);
  if (!written) streams.err << prefix << written.error() << '\n';
  return went_well && firmware_recorded && mdf_written && written ? ExitCode::success : ExitCode::failure;
}

}  // namespace duet::cli
