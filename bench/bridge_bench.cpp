// duet-bridge against socat on the same path, in the same run: firmware on a pty <-> relay <-> TCP <-> duet's master.
// - round trip of GET_STATUS (median, 99th percentile); target: the bridge's no larger than socat's;
// - three turns each, one path at a time.
// - DAQ throughput with the firmware sampling as fast as its queue allows; target: bridge / socat >= 1.0.

#include <benchmark/benchmark.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "duet/xcp/host/master.hpp"
#include "pty_firmware.hpp"
#include "relay.hpp"

namespace {

using namespace duet::xcp::host;
using duet::bridge::PtyFirmware;

struct Results {
  [[nodiscard]] double percentile(double fraction) {
    std::sort(round_trips_us.begin(), round_trips_us.end());
    return round_trips_us.empty()
               ? 0
               : round_trips_us[static_cast<std::size_t>(fraction * static_cast<double>(round_trips_us.size() - 1))];
  }
  [[nodiscard]] double megabytes_per_second() const {
    return daq_seconds > 0 ? static_cast<double>(daq_bytes) / daq_seconds / 1e6 : 0;
  }

  std::vector<double> round_trips_us;
  std::uint64_t daq_bytes = 0;
  double daq_seconds = 0;
  std::uint64_t lost = 0;
};

// One relay under test with its own firmware and master.
class Path {
 public:
  virtual ~Path() = default;
  Path() = default;
  Path(const Path&) = delete;
  Path& operator=(const Path&) = delete;

  bool connect() {
    for (int attempt = 0; attempt < 100; ++attempt) {  // socat may still be starting
      auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", port()}, std::chrono::milliseconds{1000});
      if (channel.ok()) {
        master_.emplace(std::move(channel).value());
        if (master_->connect().ok()) return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds{20});
    }
    return false;
  }

  // Appends the round trips of `count` GET_STATUS commands.
  bool time_commands(int count) {
    const std::vector<std::uint8_t> get_status{0xFD};
    for (int command = 0; command < count; ++command) {
      const auto start = std::chrono::steady_clock::now();
      if (!master_->command(get_status, "GET_STATUS").ok()) return false;
      results->round_trips_us.push_back(
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
    }
    return true;
  }

  // Receives DAQ for `duration` with the firmware sampling as fast as its queue allows (245-byte packets).
  bool stream(std::chrono::milliseconds duration) {
    const std::vector<DaqEntry> entries(60, DaqEntry{0, 0x1000, 4});
    if (!master_->start_daq({{.event = 0, .prescaler = 1, .entries = entries}}).ok()) return false;
    firmware_.flood = true;
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() < start + duration) {
      auto samples = master_->receive_samples(std::chrono::milliseconds{20});
      if (!samples.ok()) break;
      for (const DaqSample& sample : samples.value()) results->daq_bytes += sample.bytes.size();
    }
    results->daq_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    firmware_.flood = false;
    if (!master_->stop_daq().ok()) return false;
    (void)master_->receive_samples(std::chrono::milliseconds{50});  // what was on the way
    results->lost += master_->channel().counter_gaps();
    return true;
  }

  Results* results = nullptr;

 protected:
  [[nodiscard]] virtual std::uint16_t port() const = 0;
  PtyFirmware firmware_;
  std::optional<Master> master_;
};

class ThroughDuetBridge final : public Path {
 public:
  ThroughDuetBridge() : relay_{options(firmware_)} {
    if (relay_.start().ok()) thread_ = std::thread{[this] { relay_.run(); }};
  }
  ~ThroughDuetBridge() override {
    relay_.stop();
    if (thread_.joinable()) thread_.join();
  }
  ThroughDuetBridge(const ThroughDuetBridge&) = delete;
  ThroughDuetBridge& operator=(const ThroughDuetBridge&) = delete;

 private:
  static duet::bridge::RelayOptions options(PtyFirmware& firmware) {
    firmware.start();
    duet::bridge::RelayOptions options;
    options.channel.path = firmware.path();
    options.channel_uri = "tty:" + firmware.path();
    options.listen_port = 0;
    return options;
  }
  [[nodiscard]] std::uint16_t port() const override { return relay_.port(); }
  duet::bridge::Relay relay_;
  std::thread thread_;
};

class ThroughSocat final : public Path {
 public:
  ThroughSocat() {
    firmware_.start();
    socat_ = ::fork();
    if (socat_ == 0) {
      const std::string listen = "TCP-LISTEN:" + std::to_string(port_) + ",bind=127.0.0.1,reuseaddr,nodelay";
      const std::string pty = "FILE:" + firmware_.path() + ",raw,echo=0";
      ::execlp("socat", "socat", listen.c_str(), pty.c_str(), nullptr);
      ::_exit(127);
    }
  }
  ~ThroughSocat() override {
    ::kill(socat_, SIGTERM);
    ::waitpid(socat_, nullptr, 0);
  }
  ThroughSocat(const ThroughSocat&) = delete;
  ThroughSocat& operator=(const ThroughSocat&) = delete;

 private:
  [[nodiscard]] std::uint16_t port() const override { return port_; }
  std::uint16_t port_ = static_cast<std::uint16_t>(45000 + ::getpid() % 10000);
  pid_t socat_ = -1;
};

// The paths take turns, one at a time (the machine has two cores), so that the machine's moods fall on both alike.
template <typename ThroughRelay>
bool measure(Results& results) {
  ThroughRelay path;
  path.results = &results;
  return path.connect() && path.time_commands(2000) && path.stream(std::chrono::seconds{1});
}

void bridge_against_socat(benchmark::State& state) {
  Results bridge;
  Results socat;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
    for (int turn = 0; turn < 3; ++turn) {
      if (!measure<ThroughDuetBridge>(bridge) || !measure<ThroughSocat>(socat)) state.SkipWithError("a path failed");
    }
  }
  state.counters["bridge_median_us"] = bridge.percentile(0.5);
  state.counters["bridge_p99_us"] = bridge.percentile(0.99);
  state.counters["socat_median_us"] = socat.percentile(0.5);
  state.counters["socat_p99_us"] = socat.percentile(0.99);
  state.counters["bridge_MBps"] = bridge.megabytes_per_second();
  state.counters["socat_MBps"] = socat.megabytes_per_second();
  state.counters["throughput_ratio"] =
      socat.megabytes_per_second() > 0 ? bridge.megabytes_per_second() / socat.megabytes_per_second() : 0;
  state.counters["bridge_lost"] = static_cast<double>(bridge.lost);
  state.counters["socat_lost"] = static_cast<double>(socat.lost);
}
BENCHMARK(bridge_against_socat)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
