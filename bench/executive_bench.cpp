// How fast the executive runs an empty model in lock-step on the PC: the ceiling for software-in-the-loop simulation.
// Target (issue #3): at least 10 million base ticks per second.

#include <benchmark/benchmark.h>

#include "duet/host/lock_step_port.hpp"
#include "duet/rt/executive.hpp"

namespace {

void nothing() {}

constexpr duet::rt::Task tasks[] = {{.name = "base", .priority = {1, 0}, .entry = nothing}};
constexpr duet::rt::ModelDescription empty_model{
    .name = "empty", .base_period_ns = 1'000'000, .tasks = tasks, .initialize = nothing, .terminate = nothing};

void lock_step_ticks_of_an_empty_model(benchmark::State& state) {
  duet::host::LockStepPort port{empty_model};
  duet::rt::Executive<duet::host::LockStepPort, 1> executive{empty_model, port};
  port.attach(executive);
  if (executive.initialize() != duet::rt::TaskTableError::none || !executive.begin()) {
    state.SkipWithError("the model did not start");
    return;
  }
  constexpr std::uint64_t ticks_per_iteration = 1000;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
    port.advance(ticks_per_iteration);
    benchmark::DoNotOptimize(executive.ticks());
  }
  executive.end();
  state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(ticks_per_iteration));
  state.counters["ticks"] = static_cast<double>(executive.ticks());
}
BENCHMARK(lock_step_ticks_of_an_empty_model);

}  // namespace
