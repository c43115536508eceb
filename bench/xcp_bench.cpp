// XCP over localhost TCP between duet's master and a host-built slave:
// - command round trip (GET_STATUS), median and 99th percentile; target median <= 50 us;
// - sustained DAQ throughput with no loss; target >= 50 MB/s. The producer waits while the transmit queue lacks room
//   for a sample, so that nothing is dropped: what is measured is how fast the server, TCP and the master's decoding
//   carry samples away.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "duet/xcp/host/master.hpp"
#include "duet/xcp/host/slave_server.hpp"

namespace {

using namespace duet::xcp;
using namespace duet::xcp::host;

std::mutex queue_mutex;
std::uint32_t lock_queue() {
  queue_mutex.lock();
  return 0;
}
void unlock_queue(std::uint32_t) { queue_mutex.unlock(); }

constexpr std::size_t sample_bytes = 960;  // 4 ODTs of 240 bytes: a large list

struct Target {
  std::array<std::uint8_t, sample_bytes> signals{};
  std::array<MemoryRegion, 1> regions{
      MemoryRegion{.name = "signals", .address = 0x1000, .size = sample_bytes, .memory = signals.data()}};
  std::array<EventChannel, 1> events{EventChannel{.name = "step"}};
  std::array<DaqList, 1> lists{};
  std::array<Odt, 8> odts{};
  std::array<OdtEntry, 8> entries{};
  std::vector<std::uint8_t> queue_storage = std::vector<std::uint8_t>(1 << 20);
  TransmitQueue queue{queue_storage, {lock_queue, unlock_queue}};
  SlaveConfiguration configuration{.memory = MemoryMap{regions},
                                   .max_cto = 252,
                                   .max_dto = 1400,
                                   .events = events,
                                   .daq = {lists, odts, entries},
                                   .queue = &queue};
  Slave slave{configuration};
  std::mutex model_mutex;
  SlaveServer server{slave, queue, [this](const std::function<void()>& work) {
                       const std::lock_guard lock{model_mutex};
                       work();
                     }};
};

Master connect(Target& target) {
  if (!target.server.start({}).ok()) std::abort();
  auto channel =
      MasterChannel::open({Protocol::tcp, "127.0.0.1", target.server.port()}, std::chrono::milliseconds{1000});
  if (!channel.ok()) std::abort();
  Master master{std::move(channel).value()};
  if (!master.connect().ok()) std::abort();
  return master;
}

void command_round_trip(benchmark::State& state) {
  Target target;
  Master master = connect(target);
  const std::array<std::uint8_t, 1> get_status{static_cast<std::uint8_t>(Command::get_status)};
  std::vector<double> microseconds;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
    const auto start = std::chrono::steady_clock::now();
    if (!master.command(get_status, "GET_STATUS").ok()) state.SkipWithError("GET_STATUS failed");
    microseconds.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(microseconds.begin(), microseconds.end());
  state.counters["median_us"] = microseconds[microseconds.size() / 2];
  state.counters["p99_us"] = microseconds[microseconds.size() * 99 / 100];
}
BENCHMARK(command_round_trip)->Iterations(20'000)->Unit(benchmark::kMicrosecond);

void daq_throughput(benchmark::State& state) {
  Target target;
  Master master = connect(target);
  DaqListSetup list{.event = 0, .prescaler = 1};
  for (std::uint32_t offset = 0; offset < sample_bytes; offset += 240)
    list.entries.push_back({0, 0x1000 + offset, 240});
  if (!master.start_daq({list}).ok()) state.SkipWithError("DAQ did not start");
  std::uint64_t produced = 0;
  std::uint64_t received = 0;
  std::uint64_t bytes = 0;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
    constexpr std::uint64_t samples = 50'000;
    const std::uint64_t target_count = produced + samples;
    std::thread producer{[&] {
      while (produced < target_count) {
        if (target.queue.free_bytes() < 2 * (sample_bytes + 64) + 256) {  // wait for room: no sample is dropped
          target.server.notify();
          std::this_thread::yield();
          continue;
        }
        {
          const std::lock_guard lock{target.model_mutex};
          target.signals[0] = static_cast<std::uint8_t>(produced);
          target.slave.on_event(0);
        }
        ++produced;
        if (produced % 16 == 0) target.server.notify();
      }
      target.server.notify();
    }};
    while (received < target_count) {
      auto samples_received = master.receive_samples(std::chrono::milliseconds{100});
      if (!samples_received.ok()) {
        state.SkipWithError(samples_received.error().c_str());
        break;
      }
      for (const DaqSample& sample : samples_received.value()) bytes += sample.bytes.size();
      received += samples_received.value().size();
    }
    producer.join();
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
  state.counters["lost"] =
      static_cast<double>(produced - received + target.slave.overloads() + master.channel().counter_gaps());
}
BENCHMARK(daq_throughput)->Iterations(4)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
