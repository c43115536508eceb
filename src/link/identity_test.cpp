// A lock-step run through the link is the run in one process, bit for bit: duet::model::simulate against a plant in
// this process, and against the same plant served over a socket pair through RemotePlant, give identical recordings.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "duet/link/remote_plant.hpp"
#include "duet/link/serve.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/model_plant.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/plant.hpp"

namespace duet::link {
namespace {

using namespace std::chrono_literals;

struct LoadedModel {
  std::unique_ptr<model::Model> model;  // the program points into it
  std::optional<model::Program> program;
};

LoadedModel checked(Result<model::Model> loaded, const std::string& file) {
  LoadedModel result;
  if (!loaded) {
    ADD_FAILURE() << loaded.error();
    return result;
  }
  result.model = std::make_unique<model::Model>(std::move(loaded).value());
  model::ProgramBuild build = model::build_program(*result.model);
  for (const model::Diagnostic& diagnostic : build.diagnostics) ADD_FAILURE() << model::format(file, diagnostic);
  result.program = std::move(build.program);
  return result;
}

// The same doubles, bit for bit (NaN and -0 included), and the same names.
void expect_identical(const model::Recording& local, const model::Recording& remote) {
  ASSERT_EQ(local.names, remote.names);
  ASSERT_EQ(local.time_s.size(), remote.time_s.size());
  ASSERT_EQ(local.columns.size(), remote.columns.size());
  std::size_t differences = 0;
  for (std::size_t column = 0; column < local.columns.size(); ++column) {
    ASSERT_EQ(local.columns[column].size(), remote.columns[column].size());
    for (std::size_t row = 0; row < local.columns[column].size(); ++row) {
      if (std::bit_cast<std::uint64_t>(local.columns[column][row]) !=
          std::bit_cast<std::uint64_t>(remote.columns[column][row])) {
        if (++differences <= 5) {
          ADD_FAILURE() << local.names[column] << " at row " << row << ": " << local.columns[column][row] << " here, "
                        << remote.columns[column][row] << " over the link";
        }
      }
    }
  }
  EXPECT_EQ(differences, 0U);
}

// Simulates `program` against `remote_plant` served over a socket pair: the recording and how the plant's side went.
struct RemoteRun {
  model::SimulationResult result;
  ServeSummary summary;
};
RemoteRun simulate_over_link(const model::Program& program, plant::Plant& remote_plant,
                             const model::SimulationOptions& options) {
  auto pair = socket_pair(5s);
  EXPECT_TRUE(pair.ok());
  std::unique_ptr<Stream> plant_end = std::move(pair.value().second);
  std::optional<Result<ServeSummary>> served;
  std::thread plant_side{[&] { served.emplace(serve(remote_plant, *plant_end)); }};
  RemoteRun run;
  {
    auto connected = RemotePlant::connect(
        std::move(pair.value().first),
        {LinkMode::lock_step, static_cast<std::uint32_t>(std::llround(program.model->base_period_us * 1000))});
    EXPECT_TRUE(connected.ok()) << connected.error();
    if (connected) {
      auto simulated = model::simulate(program, *connected.value(), options);
      EXPECT_TRUE(simulated.ok()) << simulated.error();
      EXPECT_TRUE(connected.value()->ok()) << connected.value()->error();
      if (simulated) run.result = std::move(simulated).value();
    }
  }  // BYE
  plant_side.join();
  EXPECT_TRUE(served->ok()) << served->error();
  if (served->ok()) run.summary = served->value();
  return run;
}

TEST(LinkIdentity, TheThermostatAgainstItsHeaterModel) {
  const std::string folder = std::string{DUET_SOURCE_DIR} + "/apps/thermostat/";
  const LoadedModel thermostat = checked(model::load_model(folder + "thermostat.yaml"), "thermostat.yaml");
  ASSERT_TRUE(thermostat.program);
  auto here = model::ModelPlant::load(folder + "heater.yaml");
  auto there = model::ModelPlant::load(folder + "heater.yaml");
  ASSERT_TRUE(here.ok() && there.ok());
  const model::SimulationOptions options{20.0, {}, {}};
  auto local = model::simulate(*thermostat.program, *here.value(), options);
  ASSERT_TRUE(local.ok()) << local.error();
  const RemoteRun remote = simulate_over_link(*thermostat.program, *there.value(), options);
  EXPECT_EQ(remote.result.ticks, 2001U);
  EXPECT_EQ(remote.summary.ticks, 2001U);
  EXPECT_EQ(remote.summary.reads, 2001U);  // the ADC every tick
  EXPECT_EQ(remote.summary.hello.base_period_ns, 10'000'000U);
  expect_identical(local.value().recording, remote.result.recording);
  // The heater did switch: the run is not trivially constant.
  const model::Recording& recording = local.value().recording;
  const auto named = std::find(recording.names.begin(), recording.names.end(), "heating");
  ASSERT_NE(named, recording.names.end());
  const std::vector<double>& heating = recording.columns.at(static_cast<std::size_t>(named - recording.names.begin()));
  EXPECT_NE(std::count(heating.begin(), heating.end(), 0.0), 0);
  EXPECT_NE(std::count(heating.begin(), heating.end(), 1.0), 0);
}

// A first-order plant integrated over the time between advances (so that a time off by one bit would show), which
// raises EXTI0 when its level crosses thresholds and every 7th tick; what the interrupt task writes changes it.
class Tank : public plant::Plant {
 public:
  void advance(double time_s, const plant::RaiseInterrupt& raise) override {
    const double dt = time_s - time_s_;
    time_s_ = time_s;
    const double before = level_;
    level_ += dt * (inflow_ * duty_ - 0.8 * level_ + 0.3 * std::sin(37 * time_s));
    ++ticks_;
    if (std::floor(before) != std::floor(level_) || ticks_ % 7 == 3) raise("EXTI0");
  }
  void write(std::string_view resource, std::span<const double> values) override {
    if (resource == "pwm:TIM1/1") duty_ = values[0];
    if (resource == "gpio:LED0") inflow_ = values[0] != 0 ? 9.5 : 10.0;
  }
  void read(std::string_view resource, std::span<double> values) override {
    if (resource == "adc:ADC1/3") values[0] = std::round(level_ * 100);
    if (resource == "gpio:BUTTON") values[0] = level_ > 2.5 ? 1 : 0;
    if (resource == "probe:tank") {  // unquantised: the last bit of the plant's state shows
      values[0] = level_;
      values[1] = time_s_;
    }
    if (resource == "adc:ADC2/1") {
      values[0] = std::round(level_ * 1000);
      values[1] = std::round(time_s_ * 1000);
    }
  }

 private:
  double time_s_ = 0;
  double level_ = 0;
  double duty_ = 0;
  double inflow_ = 10;
  std::uint64_t ticks_ = 0;
};

constexpr const char* tank_controller = R"(duet_model: 1
name: tank_controller
base_period_us: 1000
signals:
  level: {measurable: true}
  duty: {measurable: true}
  presses: {measurable: true}
  sampled: {measurable: true}
blocks:
  - {name: adc, type: AdcDma, parameters: {adc: ADC1, channel: 3, count: 1}, outputs: {samples: raw}}
  - {name: to_level, type: Convert, parameters: {type: double}, inputs: {u: raw}, outputs: {y: counts}}
  - {name: scale, type: Gain, parameters: {k: 0.01}, inputs: {u: counts}, outputs: {y: level}}
  - {name: target, type: Constant, parameters: {value: 3}, outputs: {y: target}}
  - {name: error, type: Sum, parameters: {signs: "+-"}, inputs: {u1: target, u2: level}, outputs: {y: error}}
  - {name: pid, type: DiscretePid, parameters: {p: 0.7, i: 2.3, d: 0.01, lower: 0, upper: 1}, inputs: {error: error}, outputs: {y: duty}}
  - {name: probe, type: PlantInput, parameters: {resource: "probe:tank", size: 2}, outputs: {y: probe}}
  - {name: pump, type: PwmOut, parameters: {timer: TIM1, channel: 1, frequency_hz: 20000}, inputs: {duty: duty}}
  - name: isr
    type: Subsystem
    trigger: {interrupt: EXTI0, priority: 1}
    outputs: {presses: presses, sampled: sampled}
    blocks:
      - {name: button, type: GpioIn, parameters: {pin: BUTTON}, outputs: {y: high}}
      - {name: led, type: GpioOut, parameters: {pin: LED0}, inputs: {u: high}}
      - {name: count, type: Counter, parameters: {limit: 100000}, outputs: {y: counted}}
      - {name: as_double, type: Convert, parameters: {type: double}, inputs: {u: counted}, outputs: {y: presses}}
      - {name: samples, type: AdcDma, parameters: {adc: ADC2, channel: 1, count: 2}, outputs: {samples: pair}}
      - {name: pair_double, type: Convert, parameters: {type: double}, inputs: {u: pair}, outputs: {y: pair_d}}
      - {name: weigh, type: Gain, parameters: {k: [0.001, 0.5]}, inputs: {u: pair_d}, outputs: {y: sampled}}
  - {name: latest_presses, type: RateTransition, period: base, parameters: {mode: latest, initial: 0}, inputs: {u: presses}, outputs: {y: presses_seen}}
  - {name: latest_sample, type: RateTransition, period: base, parameters: {mode: latest, initial: [0, 0]}, inputs: {u: sampled}, outputs: {y: sample_seen}}
)";

TEST(LinkIdentity, InterruptsRaisedByThePlantRunTheSameTasksInTheSameTicks) {
  const LoadedModel controller = checked(model::parse_model(tank_controller, "tank.yaml"), "tank.yaml");
  ASSERT_TRUE(controller.program);
  Tank here;
  Tank there;
  const model::SimulationOptions options{3.0, {"level", "duty", "presses_seen", "sample_seen", "probe"}, {}};
  auto local = model::simulate(*controller.program, here, options);
  ASSERT_TRUE(local.ok()) << local.error();
  const RemoteRun remote = simulate_over_link(*controller.program, there, options);
  expect_identical(local.value().recording, remote.result.recording);
  EXPECT_EQ(local.value().activations, remote.result.activations);
  ASSERT_EQ(local.value().activations.size(), 2U);
  EXPECT_GT(local.value().activations[1], 400U);  // the interrupt task ran, often
  EXPECT_EQ(remote.summary.interrupts, local.value().activations[1]);
  // Each tick read two resources and wrote one; each interrupt read two and wrote one, in the middle of a tick.
  EXPECT_EQ(remote.summary.reads, 2 * remote.summary.ticks + 2 * remote.summary.interrupts);
  EXPECT_EQ(remote.summary.writes, remote.summary.ticks + remote.summary.interrupts);
}

}  // namespace
}  // namespace duet::link
