// The overhead per step of an imported FMU plant: the first-order lag test FMU (src/fmi/testing) stepped through
// FmuPlant as a simulation drives it (advance, read the output's resource, write the input's), beside the same lag
// as a native plant. docs/PERFORMANCE.md, "Simulation".
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "duet/fmu_plant/fmu_plant.hpp"

namespace {

constexpr double step_s = 0.001;
const duet::plant::RaiseInterrupt no_interrupts = [](std::string_view) {};

// y' = (k·u - y)/T stepped exactly, as the FMU's library does it, behind the plant interface.
class NativeLag : public duet::plant::Plant {
 public:
  void advance(double time_s, const duet::plant::RaiseInterrupt&) override {
    while (static_cast<double>(steps_ + 1) * step_s <= time_s + step_s * 1e-9) {
      y_ += (2.0 * u_ - y_) * (1.0 - std::exp(-step_s / 0.5));
      ++steps_;
    }
  }
  void write(std::string_view, std::span<const double> values) override { u_ = values[0]; }
  void read(std::string_view, std::span<double> values) override { values[0] = y_; }

 private:
  double u_ = 0;
  double y_ = 0;
  std::uint64_t steps_ = 0;
};

void drive(benchmark::State& state, duet::plant::Plant& plant) {
  std::uint64_t tick = 0;
  double sample = 0;
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
    plant.advance(static_cast<double>(++tick) * step_s, no_interrupts);
    plant.read("adc:ADC1/6", {&sample, 1});
    const double duty = sample < 1.0 ? 1.0 : 0.0;
    plant.write("pwm:TIM1/1", {&duty, 1});
  }
  benchmark::DoNotOptimize(sample);
  state.SetItemsProcessed(state.iterations());
}

void native_lag_step(benchmark::State& state) {
  NativeLag plant;
  drive(state, plant);
}
BENCHMARK(native_lag_step);

void fmu_lag_step(benchmark::State& state, const std::string& fmu) {
  duet::fmu_plant::FmuMapping mapping{.file = "bench",
                                      .inputs = {{.variable = "u", .resource = "pwm:TIM1/1"}},
                                      .outputs = {{.variable = "y", .resource = "adc:ADC1/6"}}};
  auto plant = duet::fmu_plant::FmuPlant::load({.fmu = std::string{DUET_TEST_FMU_DIR} + "/" + fmu, .mapping = mapping});
  if (!plant) {
    state.SkipWithError(plant.error().c_str());
    return;
  }
  if (const duet::Status started = plant.value()->start(step_s); !started) {
    state.SkipWithError(started.error().c_str());
    return;
  }
  drive(state, *plant.value());
  if (plant.value()->halted()) state.SkipWithError(plant.value()->halted()->reason.c_str());
}
BENCHMARK_CAPTURE(fmu_lag_step, fmi2, std::string{"FirstOrderLag_fmi2.fmu"});
BENCHMARK_CAPTURE(fmu_lag_step, fmi3, std::string{"FirstOrderLag_fmi3.fmu"});

}  // namespace
