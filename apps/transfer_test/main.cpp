// The thesis' XCP transfer test on the model transfer_test.yaml as duet gen generated it (generated/): the master
// finds the table, the play switch and the output in the generated A2L, downloads a table of 4096 uint16 values into
// the model's calibration segment over XCP, and sets the switch; the model, stepped every 1 ms by the executive,
// plays the table out one element per step into its output signal; DAQ on the step's event records that signal; the
// recording must equal the table element by element, with no lost packet and no overload.
//
//   transfer_test                            the slave in this process, the executive in real time (software in the
//                                            loop), reached over XCP on localhost TCP
//   transfer_test --connect tcp://HOST:PORT  a slave elsewhere: the firmware on the emulated Cortex-M4 behind
//                                            duet-bridge (run_on_qemu.sh), or on the board
//
// Exit codes: 0 every value came back, 1 the test failed, 2 the command line is wrong.

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <iostream>
#include <mutex>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "duet/host/real_time_port.hpp"
#include "duet/rt/executive.hpp"
#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/endpoint.hpp"
#include "duet/xcp/host/master.hpp"
#include "duet/xcp/host/slave_server.hpp"
#include "duet/xcp/slave.hpp"
#include "transfer_test.hpp"
#include "transfer_test_xcp.hpp"

namespace {

namespace rt = duet::rt;
namespace xcp = duet::xcp;
using duet::xcp::host::Endpoint;
using duet::xcp::host::Master;
using duet::xcp::host::MasterChannel;
using duet::xcp::host::Protocol;
using duet::xcp::host::SlaveServer;

constexpr int success = 0;
constexpr int failure = 1;
constexpr int usage = 2;
constexpr std::size_t table_size = 4096;

int fail(const std::string& message) {
  std::cerr << "transfer test: " << message << '\n';
  return failure;
}

std::mutex queue_mutex;
std::uint32_t lock_queue() {
  queue_mutex.lock();
  return 0;
}
void unlock_queue(std::uint32_t) { queue_mutex.unlock(); }

// The executive's clock for DAQ timestamps, in microseconds (the slave's default timestamp unit).
std::uint32_t microseconds() { return static_cast<std::uint32_t>(duet::host::RealTimePort::monotonic_ns() / 1000U); }

// The slave's side: the model's slave as its generated code sizes it.
struct Target {
  transfer_test::xcp::Slave slave{{.timestamp = microseconds, .queue_lock = {lock_queue, unlock_queue}}};
};

// Where the A2L says a variable is.
struct Addresses {
  std::uint32_t table = 0;
  std::uint32_t playing = 0;
  std::uint32_t output = 0;
};

duet::Result<Addresses> addresses_from_a2l() {
  auto text = duet::read_text_file(DUET_TRANSFER_TEST_A2L);
  if (!text) return duet::Failure{text.error()};
  auto a2l = xcp::host::read_a2l(text.value(), DUET_TRANSFER_TEST_A2L);
  if (!a2l) return duet::Failure{a2l.error()};
  Addresses found;
  for (const auto& characteristic : a2l.value().characteristics) {
    if (characteristic.name == "table") found.table = characteristic.address;
    if (characteristic.name == "playing") found.playing = characteristic.address;
  }
  for (const auto& measurement : a2l.value().measurements) {
    if (measurement.name == "output") found.output = measurement.address;
  }
  if (found.table == 0 || found.playing == 0 || found.output == 0) {
    return duet::Failure{"the A2L lacks table, playing or output"};
  }
  return found;
}

// The executive's port, whose tasks sample their DAQ lists right after their step.
class XcpPort : public duet::host::RealTimePort {
 public:
  XcpPort(const rt::ModelDescription& model_description, Target& target)
      : RealTimePort(model_description), target_(target) {}
  void task_finished(std::size_t task) {
    target_.slave.protocol().on_event(static_cast<std::uint16_t>(task));
    if (server != nullptr) server->notify();
  }
  SlaveServer* server = nullptr;

 private:
  Target& target_;
};

// What the master saw of the play-out.
struct Recording {
  std::size_t equal = 0;     // elements equal to the table's
  std::size_t recorded = 0;  // elements recorded (table_size unless samples stopped coming)
  std::uint64_t lost_packets = 0;
  std::uint64_t overload_events = 0;  // EV_DAQ_OVERLOAD: the slave dropped samples
  double mean_step_us = 0;            // by the slave's timestamps
  double wall_s = 0;                  // from the play-out's first sample to its last, as they arrived here

  [[nodiscard]] bool complete() const { return equal == table_size && lost_packets == 0 && overload_events == 0; }
};

// The master's part, whoever the slave is: downloads the table (and reads it back), starts DAQ on the step's event,
// starts the play-out and records it.
duet::Result<Recording> play_the_table(Master& master, const Addresses& at) {
  std::vector<std::uint16_t> table(table_size);
  std::mt19937 random{2026};  // a fixed seed: every run sends the same table
  for (std::uint16_t& value : table) value = static_cast<std::uint16_t>(random());
  std::vector<std::uint8_t> bytes;
  for (std::uint16_t value : table) {
    bytes.push_back(static_cast<std::uint8_t>(value));
    bytes.push_back(static_cast<std::uint8_t>(value >> 8U));
  }
  if (auto connected = master.connect(); !connected) return duet::Failure{connected.error()};
  for (std::size_t offset = 0; offset < bytes.size(); offset += 250) {  // the table, 125 values per DOWNLOAD
    const std::size_t size = std::min<std::size_t>(250, bytes.size() - offset);
    if (auto written =
            master.download(0, at.table + static_cast<std::uint32_t>(offset), std::span{bytes}.subspan(offset, size));
        !written) {
      return duet::Failure{written.error()};
    }
  }
  auto checked = master.upload(0, at.table, static_cast<std::uint32_t>(bytes.size()));
  if (!checked) return duet::Failure{checked.error()};
  if (checked.value() != bytes) return duet::Failure{"the table did not arrive as it was sent"};
  if (auto started = master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, at.output, 2}}}}); !started) {
    return duet::Failure{started.error()};
  }
  const std::array<std::uint8_t, 1> on{1};
  if (auto playing = master.download(0, at.playing, on); !playing) return duet::Failure{playing.error()};

  // Samples before the play-out began repeat the initial output (0); the play-out itself is the table, once per step.
  std::vector<std::uint16_t> recorded;
  std::vector<std::int64_t> ticks;
  std::chrono::steady_clock::time_point first_arrival;
  std::chrono::steady_clock::time_point last_arrival;
  bool started = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds{30};
  while (recorded.size() < table_size && std::chrono::steady_clock::now() < deadline) {
    auto samples = master.receive_samples(std::chrono::milliseconds{100});
    if (!samples) return duet::Failure{samples.error()};
    const auto arrival = std::chrono::steady_clock::now();
    for (const duet::xcp::host::DaqSample& sample : samples.value()) {
      const auto value = static_cast<std::uint16_t>(sample.bytes[0] | (sample.bytes[1] << 8U));
      if (!started && value == table[0]) {
        started = true;
        first_arrival = arrival;
      }
      if (!started) continue;
      if (recorded.size() < table_size) {
        recorded.push_back(value);
        ticks.push_back(sample.ticks);
        last_arrival = arrival;
      }
    }
  }
  (void)master.stop_daq();
  (void)master.disconnect();

  Recording recording{.recorded = recorded.size(),
                      .lost_packets = master.counters().lost() - master.overload_events(),
                      .overload_events = master.overload_events(),
                      .wall_s = std::chrono::duration<double>(last_arrival - first_arrival).count()};
  for (std::size_t index = 0; index < recorded.size(); ++index)
    recording.equal += recorded[index] == table[index] ? 1U : 0U;
  // The steps' timestamps: one period apart on average; the slave's clock stamped them, not the master's arrival.
  // The master counts them on across the clock's wraps.
  if (ticks.size() > 1) {
    recording.mean_step_us = static_cast<double>(ticks.back() - ticks.front()) * master.seconds_per_tick() * 1e6 /
                             static_cast<double>(ticks.size() - 1);
  }
  return recording;
}

void print(const Recording& recording, const std::string& slave_side) {
  std::cout << "transfer test: " << recording.equal << " of " << table_size
            << " values recorded equal to the table sent (" << recording.recorded << " recorded, "
            << recording.lost_packets << " lost packets, " << recording.overload_events << " overloads" << slave_side
            << "; mean step by the DAQ timestamps " << recording.mean_step_us << " us; the play-out arrived in "
            << recording.wall_s << " s)\n";
}

// Software in the loop: the slave and the executive in this process, in real time, XCP on localhost TCP.
int run_in_process(const Addresses& at) {
  const auto target_storage = std::make_unique<Target>();  // 64 KB of queue: not on the stack
  Target& target = *target_storage;
  const rt::ModelDescription& description = transfer_test::description;
  XcpPort port{description, target};
  rt::Executive<XcpPort, 1> executive{description, port};
  port.attach(executive);
  SlaveServer server{target.slave.protocol(), target.slave.queue(),
                     [&port](const std::function<void()>& work) { port.exclusive(work); }};
  port.server = &server;
  if (!server.start({}).ok() || executive.initialize() != rt::TaskTableError::none || !executive.begin()) {
    return fail("the target did not start");
  }
  auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", server.port()}, std::chrono::milliseconds{1000});
  if (!channel) return fail(channel.error());
  Master master{std::move(channel).value()};
  auto recording = play_the_table(master, at);
  executive.request_stop(rt::StopReason::external);
  executive.end();
  server.stop();
  if (!recording) return fail(recording.error());

  // The slave's own counts too: what it could not queue, and steps that overran.
  const std::uint32_t overruns = executive.statistics(0).overruns;
  print(recording.value(), ", " + std::to_string(overruns) + " overruns");
  return recording.value().complete() && target.slave.protocol().overloads() == 0 && overruns == 0 ? success : failure;
}

// A slave elsewhere: its own console tells of its overruns.
int run_against(const Endpoint& slave, const Addresses& at) {
  // Generous: a command's answer may wait behind the slave's start, or behind DAQ on a slow line.
  auto channel = MasterChannel::open(slave, std::chrono::milliseconds{5000});
  if (!channel) return fail(channel.error());
  Master master{std::move(channel).value(), std::chrono::milliseconds{5000}};
  auto recording = play_the_table(master, at);
  if (!recording) return fail(recording.error());
  print(recording.value(), " at " + duet::xcp::host::to_string(slave));
  return recording.value().complete() ? success : failure;
}

int parse_and_run(int argc, char** argv) {
  std::string connect;
  CLI::App app{"The thesis' XCP transfer test: 4096 values down, played out one per 1 ms step, recorded by DAQ",
               "transfer_test"};
  app.footer("Exit codes: 0 every value came back, 1 the test failed, 2 the command line is wrong.");
  app.add_option("--connect", connect,
                 "The slave at tcp://HOST:PORT or udp://HOST:PORT (default: one in this process, in real time)")
      ->type_name("URI")
      ->check(CLI::Validator(
          [](const std::string& text) {
            auto parsed = duet::xcp::host::parse_endpoint(text);
            return parsed ? std::string{} : parsed.error();
          },
          ""));
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "transfer_test: " << error.what() << ". See 'transfer_test --help'.\n";
    return usage;
  }
  const auto addresses = addresses_from_a2l();
  if (!addresses) return fail(addresses.error());
  if (connect.empty()) return run_in_process(addresses.value());
  return run_against(duet::xcp::host::parse_endpoint(connect).value(), addresses.value());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return parse_and_run(argc, argv);
  } catch (const std::exception& error) {  // a bug or an exhausted machine: say so instead of aborting
    std::cerr << "transfer test: internal error: " << error.what() << '\n';
    return failure;
  }
}
