// The thesis' XCP transfer test, in software in the loop, on the model transfer_test.yaml as duet gen generated it
// (generated/): the master finds the table, the play switch and the output in the generated A2L, downloads a table of
// 4096 uint16 values into the model's calibration segment over XCP on TCP, and sets the switch; the model, stepped
// every 1 ms by the executive in real time, plays the table out one element per step into its output signal; DAQ on
// the step's event records that signal; the recording must equal the table element by element.

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
#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/master.hpp"
#include "duet/xcp/host/slave_server.hpp"
#include "duet/xcp/slave.hpp"
#include "transfer_test.hpp"
#include "transfer_test_xcp.hpp"

namespace {

namespace rt = duet::rt;
namespace xcp = duet::xcp;
using duet::xcp::host::Master;
using duet::xcp::host::MasterChannel;
using duet::xcp::host::Protocol;
using duet::xcp::host::SlaveServer;

constexpr std::size_t table_size = 4096;

std::mutex queue_mutex;
std::uint32_t lock_queue() {
  queue_mutex.lock();
  return 0;
}
void unlock_queue(std::uint32_t) { queue_mutex.unlock(); }

// The executive's clock for DAQ timestamps, in microseconds (the slave's default timestamp unit).
std::uint32_t microseconds() { return static_cast<std::uint32_t>(duet::host::RealTimePort::monotonic_ns() / 1000U); }

// The slave's side: the model's memory as the generated code declares it to XCP, DAQ storage, the queue, the server.
struct Target {
  std::array<xcp::CalibrationSegment, 1> segments{transfer_test::xcp::calibration_segment()};
  std::array<xcp::MemoryRegion, 1> regions{transfer_test::xcp::signals_region()};
  std::array<xcp::DaqList, 1> lists{};
  std::array<xcp::Odt, 1> odts{};
  std::array<xcp::OdtEntry, 1> entries{};
  std::vector<std::uint8_t> queue_storage = std::vector<std::uint8_t>(1 << 16);
  std::array<std::uint8_t, 256> download_buffer{};
  xcp::TransmitQueue queue{queue_storage, {lock_queue, unlock_queue}};
  xcp::SlaveConfiguration configuration{.memory = xcp::MemoryMap{regions},
                                        .segments = segments,
                                        .max_cto = 252,
                                        .download_buffer = download_buffer,
                                        .events = transfer_test::xcp::events,
                                        .daq = {lists, odts, entries},
                                        .queue = &queue,
                                        .timestamp = microseconds};
  xcp::Slave slave{configuration};
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
    target_.slave.on_event(static_cast<std::uint16_t>(task));
    if (server != nullptr) server->notify();
  }
  SlaveServer* server = nullptr;

 private:
  Target& target_;
};

}  // namespace

int run_transfer_test() {
  const auto addresses = addresses_from_a2l();
  if (!addresses) {
    std::cerr << "transfer test: " << addresses.error() << '\n';
    return 1;
  }
  const Addresses& at = addresses.value();
  Target target;
  const rt::ModelDescription& description = transfer_test::description;
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
  for (std::size_t offset = 0; offset < bytes.size(); offset += 250) {  // the table, 125 values per DOWNLOAD
    const std::size_t size = std::min<std::size_t>(250, bytes.size() - offset);
    if (auto written =
            master.download(0, at.table + static_cast<std::uint32_t>(offset), std::span{bytes}.subspan(offset, size));
        !written) {
      return fail(written.error());
    }
  }
  auto checked = master.upload(0, at.table, static_cast<std::uint32_t>(bytes.size()));
  if (!checked || checked.value() != bytes) return fail("the table did not arrive as it was sent");
  if (auto started = master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, at.output, 2}}}}); !started) {
    return fail(started.error());
  }
  const std::array<std::uint8_t, 1> on{1};
  if (auto playing = master.download(0, at.playing, on); !playing) {
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
