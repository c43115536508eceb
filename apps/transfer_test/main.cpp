// The thesis' XCP transfer test, in software in the loop: the master downloads a table of 4096 uint16 values into the
// model's parameters over XCP on TCP; the model, stepped every 1 ms by the executive in real time, plays the table
// out one element per step into a signal; DAQ on the step's event records that signal through the master; the
// recording must equal the table element by element.

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <iostream>
#include <mutex>
#include <random>
#include <thread>
#include <vector>

#include "duet/host/real_time_port.hpp"
#include "duet/rt/executive.hpp"
#include "duet/xcp/host/master.hpp"
#include "duet/xcp/host/slave_server.hpp"
#include "duet/xcp/slave.hpp"

namespace {

namespace rt = duet::rt;
namespace xcp = duet::xcp;
using duet::xcp::host::Master;
using duet::xcp::host::MasterChannel;
using duet::xcp::host::Protocol;
using duet::xcp::host::SlaveServer;

constexpr std::size_t table_size = 4096;

// The model's parameters (tunable over XCP), its signal, and where the play-out stands.
struct Parameters {
  std::array<std::uint16_t, table_size> table;
  std::uint8_t playing;  // the master starts the play-out
};
Parameters parameters{};
std::uint16_t output = 0;
std::uint32_t played = 0;

void step() {
  if (parameters.playing != 0 && played < table_size) output = parameters.table[played++];
}
void nothing() {}

constexpr rt::Task tasks[] = {{.name = "1 ms", .priority = {1, 0}, .entry = step}};
constexpr rt::ModelDescription description{
    .name = "transfer test", .base_period_ns = 1'000'000, .tasks = tasks, .initialize = nothing, .terminate = nothing};

std::mutex queue_mutex;
std::uint32_t lock_queue() {
  queue_mutex.lock();
  return 0;
}
void unlock_queue(std::uint32_t) { queue_mutex.unlock(); }

// The executive's clock for DAQ timestamps, in microseconds (the slave's default timestamp unit).
std::uint32_t microseconds() { return static_cast<std::uint32_t>(duet::host::RealTimePort::monotonic_ns() / 1000U); }

// The slave's side: memory declared to XCP, DAQ storage, the queue, the server.
struct Target {
  std::array<xcp::MemoryRegion, 2> regions{xcp::MemoryRegion{.name = "signals",
                                                             .address = 0x1000,
                                                             .size = sizeof(output),
                                                             .memory = reinterpret_cast<std::uint8_t*>(&output)},
                                           xcp::MemoryRegion{.name = "parameters",
                                                             .address = 0x10000,
                                                             .size = sizeof(Parameters),
                                                             .memory = reinterpret_cast<std::uint8_t*>(&parameters),
                                                             .access = xcp::Access::read_write}};
  std::array<xcp::EventChannel, 1> events{xcp::EventChannel{.name = "1 ms", .time_cycle = 1, .time_unit = 6}};
  std::array<xcp::DaqList, 1> lists{};
  std::array<xcp::Odt, 1> odts{};
  std::array<xcp::OdtEntry, 1> entries{};
  std::vector<std::uint8_t> queue_storage = std::vector<std::uint8_t>(1 << 16);
  std::array<std::uint8_t, 256> download_buffer{};
  xcp::TransmitQueue queue{queue_storage, {lock_queue, unlock_queue}};
  xcp::SlaveConfiguration configuration{.memory = xcp::MemoryMap{regions},
                                        .max_cto = 252,
                                        .download_buffer = download_buffer,
                                        .events = events,
                                        .daq = {lists, odts, entries},
                                        .queue = &queue,
                                        .timestamp = microseconds};
  xcp::Slave slave{configuration};
};

// The executive's port, whose tasks sample their DAQ lists right after their step.
class XcpPort : public duet::host::RealTimePort {
 public:
  XcpPort(const rt::ModelDescription& model_description, Target& target)
      : RealTimePort(model_description), target_(target) {}
  void task_finished(std::size_t task) {
    target_.slave.on_event(static_cast<std::uint16_t>(task));
    if (server != nullptr) server->notify();
  }
  SlaveServer* server = nullptr;

 private:
  Target& target_;
};

}  // namespace

int run_transfer_test() {
  Target target;
  XcpPort port{description, target};
  rt::Executive<XcpPort, 1> executive{description, port};
  port.attach(executive);
  SlaveServer server{target.slave, target.queue, [&port](const std::function<void()>& work) { port.exclusive(work); }};
  port.server = &server;
  if (!server.start({}).ok() || executive.initialize() != rt::TaskTableError::none || !executive.begin()) {
    std::cerr << "transfer test: the target did not start\n";
    return 1;
  }

  auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", server.port()}, std::chrono::milliseconds{1000});
  if (!channel) {
    std::cerr << "transfer test: " << channel.error() << '\n';
    return 1;
  }
  Master master{std::move(channel).value()};
  std::vector<std::uint16_t> table(table_size);
  std::mt19937 random{2026};  // a fixed seed: every run sends the same table
  for (std::uint16_t& value : table) value = static_cast<std::uint16_t>(random());
  std::vector<std::uint8_t> bytes;
  for (std::uint16_t value : table) {
    bytes.push_back(static_cast<std::uint8_t>(value));
    bytes.push_back(static_cast<std::uint8_t>(value >> 8U));
  }
  const auto fail = [](const std::string& message) {
    std::cerr << "transfer test: " << message << '\n';
    return 1;
  };
  if (auto connected = master.connect(); !connected) return fail(connected.error());
  for (std::size_t at = 0; at < bytes.size(); at += 250) {  // the table, 125 values per DOWNLOAD
    const std::size_t size = std::min<std::size_t>(250, bytes.size() - at);
    if (auto written = master.download(0, 0x10000 + static_cast<std::uint32_t>(at), std::span{bytes}.subspan(at, size));
        !written) {
      return fail(written.error());
    }
  }
  auto checked = master.upload(0, 0x10000, static_cast<std::uint32_t>(bytes.size()));
  if (!checked || checked.value() != bytes) return fail("the table did not arrive as it was sent");
  if (auto started = master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 2}}}}); !started) {
    return fail(started.error());
  }
  const std::array<std::uint8_t, 1> on{1};
  if (auto playing = master.download(0, 0x10000 + offsetof(Parameters, playing), on); !playing) {
    return fail(playing.error());
  }

  // Samples before the play-out began repeat the initial output (0); the play-out itself is the table, once per step.
  std::vector<std::uint16_t> recorded;
  std::vector<std::uint32_t> timestamps;
  bool started = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds{30};
  while (recorded.size() < table_size && std::chrono::steady_clock::now() < deadline) {
    auto samples = master.receive_samples(std::chrono::milliseconds{100});
    if (!samples) return fail(samples.error());
    for (const duet::xcp::host::DaqSample& sample : samples.value()) {
      const auto value = static_cast<std::uint16_t>(sample.bytes[0] | (sample.bytes[1] << 8U));
      if (!started && value == table[0]) started = true;
      if (!started) continue;
      if (recorded.size() < table_size) {
        recorded.push_back(value);
        timestamps.push_back(sample.timestamp);
      }
    }
  }
  (void)master.stop_daq();
  (void)master.disconnect();
  executive.request_stop(rt::StopReason::external);
  executive.end();
  server.stop();

  std::size_t equal = 0;
  for (std::size_t index = 0; index < recorded.size(); ++index) equal += recorded[index] == table[index] ? 1U : 0U;
  // The steps' timestamps: one period apart on average; the executive's clock stamped them, not the master's arrival.
  const double mean_step_us = timestamps.size() > 1 ? static_cast<double>(timestamps.back() - timestamps.front()) /
                                                          static_cast<double>(timestamps.size() - 1)
                                                    : 0;
  std::cout << "transfer test: " << equal << " of " << table_size << " values recorded equal to the table sent ("
            << recorded.size() << " recorded, " << master.channel().counter_gaps() << " lost packets, "
            << target.slave.overloads() << " overloads, " << executive.statistics(0).overruns
            << " overruns; mean step by the DAQ timestamps " << mean_step_us << " us)\n";
  return equal == table_size && master.channel().counter_gaps() == 0 && target.slave.overloads() == 0 ? 0 : 1;
}

int main() {
  try {
    return run_transfer_test();
  } catch (const std::exception& error) {  // a bug or an exhausted machine: say so instead of aborting
    std::cerr << "transfer test: internal error: " << error.what() << '\n';
    return 1;
  }
}
