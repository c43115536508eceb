// A target for the dashboard's latency benchmark (bench/dashboard_latency.sh): an XCP slave on the PC whose first
// signal is the wall-clock time at which the target took the sample, in ms since the Unix epoch, so that a browser on
// the same machine can tell how long the sample took to reach it; seven sines make eight signals, sampled by DAQ on
// a 1 ms event. Writes its A2L to the file given and prints "listening tcp://127.0.0.1:PORT".
#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <iostream>
#include <mutex>
#include <thread>

#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/slave_server.hpp"
#include "duet/xcp/slave.hpp"
#include "test_target.hpp"

namespace {

using namespace duet::xcp;
using namespace duet::xcp::host;

std::uint32_t microseconds() {
  const auto now = std::chrono::steady_clock::now().time_since_epoch();
  return static_cast<std::uint32_t>(std::chrono::duration_cast<std::chrono::microseconds>(now).count());
}

volatile std::sig_atomic_t stopped = 0;

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: dashboard_target A2L_FILE\n";
    return 2;
  }
  std::array<double, 8> signals{};
  std::array<std::uint8_t, 8> parameters{}, reference{};
  const std::uint8_t* volatile ecu_page = parameters.data();
  const std::array<MemoryRegion, 1> regions{MemoryRegion{.name = "signals",
                                                         .address = 0x1000,
                                                         .size = sizeof signals,
                                                         .memory = reinterpret_cast<std::uint8_t*>(&signals)}};
  const std::array<CalibrationSegment, 1> segments{CalibrationSegment{.name = "parameters",
                                                                      .address = 0x2000,
                                                                      .size = 8,
                                                                      .working = parameters.data(),
                                                                      .reference = reference.data(),
                                                                      .ecu_page = &ecu_page}};
  const std::array<EventChannel, 1> events{EventChannel{.name = "1 ms", .time_cycle = 1, .time_unit = 6}};
  std::array<DaqList, 2> lists{};
  std::array<Odt, 8> odts{};
  std::array<OdtEntry, 16> entries{};
  static std::array<std::uint8_t, 1 << 18> queue_storage{};
  std::array<std::uint8_t, 256> download_buffer{};
  TransmitQueue queue{queue_storage, {lock_test_queue, unlock_test_queue}};  // test_target.hpp's lock
  const SlaveConfiguration configuration{.memory = MemoryMap{regions},
                                         .segments = segments,
                                         .max_cto = 248,
                                         .max_dto = 248,
                                         .identification = "dashboard_target",
                                         .download_buffer = download_buffer,
                                         .events = events,
                                         .daq = {lists, odts, entries},
                                         .queue = &queue,
                                         .timestamp = microseconds,
                                         .timestamp_unit = 3,
                                         .timestamp_ticks = 1};
  Slave slave{configuration};
  std::mutex model;
  SlaveServer server{slave, queue, [&model](const std::function<void()>& work) {
                       const std::lock_guard lock{model};
                       work();
                     }};
  if (auto started = server.start({}); !started) {
    std::cerr << "dashboard_target: " << started.error() << '\n';
    return 1;
  }
  A2lDescription a2l;
  a2l.module = "dashboard_target";
  a2l.memory = {{"signals", 0, 0x1000, sizeof signals, false}, {"parameters", 0, 0x2000, 8, true}};
  a2l.measurements.push_back(
      {"wall_clock_ms", "when the sample was taken", DataType::float64, 0, 0x1000, 1, "ms", 0, 1e15, {}});
  for (std::uint32_t k = 1; k < signals.size(); ++k) {
    a2l.measurements.push_back(
        {"sine_" + std::to_string(k), "a sine", DataType::float64, 0, 0x1000 + 8 * k, 1, "", -1, 1, {}});
  }
  a2l.characteristics = {{"gain", "a gain", DataType::float32, 0, 0x2000, 1, "", 0, 100, {}}};
  a2l.events = {{"1 ms", 0, 1, 6, 0}};
  a2l.max_cto = 248;
  a2l.max_dto = 248;
  a2l.transport = {Protocol::tcp, "127.0.0.1", server.port()};
  std::ofstream{argv[1]} << write_a2l(a2l);
  std::cout << "listening tcp://127.0.0.1:" << server.port() << std::endl;

  std::signal(SIGINT, [](int) { stopped = 1; });
  std::signal(SIGTERM, [](int) { stopped = 1; });
  auto next = std::chrono::steady_clock::now();
  for (std::uint64_t step = 0; stopped == 0; ++step) {
    next += std::chrono::milliseconds{1};
    std::this_thread::sleep_until(next);
    {
      const std::lock_guard lock{model};
      const auto wall = std::chrono::system_clock::now().time_since_epoch();
      signals[0] = std::chrono::duration<double, std::milli>(wall).count();
      for (std::size_t k = 1; k < signals.size(); ++k)
        signals[k] = std::sin(2 * M_PI * static_cast<double>(k) * 0.5 * static_cast<double>(step) * 1e-3);
      slave.on_event(0);
    }
    server.notify();
  }
  return 0;
}
