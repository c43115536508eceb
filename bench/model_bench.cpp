// Benchmarks of the model tools on the PC: generating the code of the largest example (target < 1 s, issue #7), and
// simulating it.
#include <benchmark/benchmark.h>

#include "duet/model/generate.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "sil_run.hpp"

namespace {

// The largest example by generated code: the transfer test's 4096-element table.
const std::string largest_example = std::string{DUET_SOURCE_DIR} + "/apps/transfer_test/transfer_test.yaml";

// What `duet gen` does: read, validate, type, lay out, and generate every file (not the writing).
void generate_largest_example(benchmark::State& state) {
  for (auto _ : state) {
    auto model = duet::model::load_model(largest_example);
    const duet::model::ProgramBuild build = duet::model::build_program(model.value());
    auto files = duet::model::generate(*build.program, "transfer_test.yaml");
    benchmark::DoNotOptimize(files.value().front().text.data());
  }
}
BENCHMARK(generate_largest_example)->Unit(benchmark::kMillisecond);

// Simulated base ticks per second of the transfer test, playing.
void simulate_transfer_test(benchmark::State& state) {
  auto model = duet::model::load_model(largest_example);
  const duet::model::ProgramBuild build = duet::model::build_program(model.value());
  constexpr double seconds = 10.0;
  for (auto _ : state) {
    duet::plant::Loopback plant;
    duet::model::SimulationOptions options;
    options.duration_s = seconds;
    options.before_tick = [](std::uint64_t tick, duet::model::Interpreter& interpreter) {
      if (tick == 0) interpreter.set_parameter(1, 0, 1);
    };
    auto result = duet::model::simulate(*build.program, plant, options);
    benchmark::DoNotOptimize(result.value().ticks);
  }
  state.counters["ticks_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * seconds * 1000.0, benchmark::Counter::kIsRate);
}
BENCHMARK(simulate_transfer_test)->Unit(benchmark::kMillisecond);

// The robot's closed loop as `duet sim` runs it: a minute at 1 kHz control, the controller model interpreted, the
// simulated robot with every sensor's interrupts (held at 5 degrees until 2 s, then balancing). Target: >= 1000 times
// real time (issue #8), i.e. under 60 ms per iteration.
void simulate_balbot_minute(benchmark::State& state) {
  auto model = duet::model::load_model(std::string{DUET_SOURCE_DIR} + "/apps/balbot/balbot.yaml");
  const duet::model::ProgramBuild build = duet::model::build_program(model.value());
  constexpr double seconds = 60.0;
  for (auto _ : state) {
    duet::plant::BalbotScenario scenario;
    scenario.release_time_s = 2;
    const auto plant = duet::plant::make_balbot_plant(scenario);
    duet::model::SimulationOptions options;
    options.duration_s = seconds;
    options.signals = {"theta"};  // what a user would plot; the recording is not what is measured here
    options.record_plant = false;
    auto result = duet::model::simulate(*build.program, *plant, options);
    benchmark::DoNotOptimize(result.value().ticks);
  }
  state.counters["times_real_time"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * seconds, benchmark::Counter::kIsRate);
}
BENCHMARK(simulate_balbot_minute)->Unit(benchmark::kMillisecond);

// The same minute with the robot's generated firmware built for the PC (apps/balbot/sil_run.hpp, as balbot_sil
// --plant balbot runs it): the firmware's steps on the lock-step executive, the simulated robot in the same process.
void firmware_balbot_minute(benchmark::State& state) {
  constexpr double seconds = 60.0;
  for (auto _ : state) {
    duet::plant::BalbotScenario scenario;
    scenario.release_time_s = 2;
    const auto plant = duet::plant::make_balbot_plant(scenario);
    duet::sil::SilOptions options;
    options.duration_s = seconds;
    auto result = duet::sil::run_sil(*plant, options);
    benchmark::DoNotOptimize(result.value().ticks);
  }
  state.counters["times_real_time"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * seconds, benchmark::Counter::kIsRate);
}
BENCHMARK(firmware_balbot_minute)->Unit(benchmark::kMillisecond);

}  // namespace
