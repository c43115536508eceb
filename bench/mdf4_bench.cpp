// Writing MDF 4 on the PC: samples of 16 f64 signals (a 1 kHz recording's group) appended and finalised, in bytes and
// samples per second. docs/PERFORMANCE.md, "Recording".
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "duet/mdf4/writer.hpp"

namespace {

constexpr std::size_t signals = 16;
constexpr std::int64_t samples_per_file = 1'000'000;
constexpr std::size_t record_bytes = 8 + signals * 8 + 2;  // time, values, invalidation bits

duet::mdf4::FileSpec sixteen_signals() {
  duet::mdf4::GroupSpec group{.name = "rate 1", .comment = "", .channels = {}};
  group.channels.push_back({.name = "signal", .type = duet::mdf4::ValueType::f64, .elements = signals});
  return duet::mdf4::FileSpec{.groups = {group}};
}

void write_sixteen_signals(benchmark::State& state) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("duet_mdf4_bench_" + std::to_string(::getpid()) + ".mf4");
  std::vector<duet::mdf4::Value> values(signals);
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
    auto writer = duet::mdf4::Writer::create(file, sixteen_signals());
    for (std::int64_t sample = 0; sample < samples_per_file; ++sample) {
      for (std::size_t signal = 0; signal < signals; ++signal)
        values[signal] = static_cast<double>(sample) + static_cast<double>(signal);
      if (!writer.value().append(0, static_cast<double>(sample) * 0.001, values)) state.SkipWithError("append");
    }
    if (!writer.value().finalise()) state.SkipWithError("finalise");
  }
  std::filesystem::remove(file);
  state.SetItemsProcessed(state.iterations() * samples_per_file);
  state.SetBytesProcessed(state.iterations() * samples_per_file * static_cast<std::int64_t>(record_bytes));
}
// Rates by CPU time: the wall time (shown beside) is mostly the disk, and the final sync, on a shared machine.
BENCHMARK(write_sixteen_signals)->Unit(benchmark::kMillisecond);

}  // namespace
