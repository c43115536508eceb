// Back to back: each example's generated code, built for the PC, computes bit for bit what duet sim's interpreter
// computes from the model, tick by tick, with the same tuning at the same ticks and the same traffic to the plant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <iterator>
#include <memory>
#include <random>

#include "balbot.hpp"
#include "block_tour.hpp"
#include "duet/hardware/hardware.hpp"
#include "duet/host/lock_step_port.hpp"
#include "duet/model/generate.hpp"
#include "duet/model/model_file.hpp"
#include "duet/model/model_plant.hpp"
#include "duet/model/program.hpp"
#include "duet/model/simulation.hpp"
#include "duet/plant/balbot/balbot_plant.hpp"
#include "duet/rt/executive.hpp"
#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"
#include "examples.hpp"
#include "pid_demo.hpp"
#include "step_time.hpp"
#include "thermostat.hpp"
#include "tilt_reference.hpp"
#include "transfer_test.hpp"

namespace duet::model {
namespace {

// The plant an example runs against: a Loopback, or a plant that is itself a model.
using PlantFactory = std::function<std::unique_ptr<plant::Plant>()>;

// Remembers every write and every read, in order, with the values, and hands them to the plant behind it.
class LoggingPlant : public plant::Plant {
 public:
  explicit LoggingPlant(const PlantFactory& factory)
      : behind_{factory ? factory() : std::make_unique<plant::Loopback>()} {}
  void advance(double time_s, const plant::RaiseInterrupt& raise) override { behind_->advance(time_s, raise); }
  void write(std::string_view resource, std::span<const double> values) override {
    log.emplace_back("write " + std::string{resource}, std::vector<double>(values.begin(), values.end()));
    behind_->write(resource, values);
  }
  void read(std::string_view resource, std::span<double> values) override {
    behind_->read(resource, values);
    log.emplace_back("read " + std::string{resource}, std::vector<double>(values.begin(), values.end()));
  }
  std::vector<std::pair<std::string, std::vector<double>>> log;

 private:
  std::unique_ptr<plant::Plant> behind_;
};

struct Example {
  std::string name;
  const rt::ModelDescription& description;
  const void* signals;  // the generated Signals structure
  std::uint64_t ticks;
  std::function<void(std::uint64_t tick, Interpreter& model)> tune_interpreted;
  std::function<void(std::uint64_t tick)> tune_generated;
  PlantFactory plant;  // none: a Loopback
  // Measurements that must change over the run: what the example is there to cover.
  std::vector<std::string> changing;
};

// A plant model from the examples' folders, a new instance of it each call.
PlantFactory plant_model(const std::string& file) {
  return [file]() -> std::unique_ptr<plant::Plant> {
    auto plant = ModelPlant::load(std::string{DUET_SOURCE_DIR} + "/apps/" + file);
    if (!plant.ok()) {
      ADD_FAILURE() << plant.error();
      return std::make_unique<plant::Loopback>();
    }
    EXPECT_TRUE(plant.value()->warnings().empty());
    return std::move(plant).value();
  };
}

double decode(xcp::host::DataType type, const std::byte* at) {
  const auto read = [at]<typename T>(T) {
    T value;
    std::memcpy(&value, at, sizeof(T));
    return static_cast<double>(value);
  };
  switch (type) {
    case xcp::host::DataType::uint8: return read(std::uint8_t{});
    case xcp::host::DataType::int8: return read(std::int8_t{});
    case xcp::host::DataType::uint16: return read(std::uint16_t{});
    case xcp::host::DataType::int16: return read(std::int16_t{});
    case xcp::host::DataType::uint32: return read(std::uint32_t{});
    case xcp::host::DataType::int32: return read(std::int32_t{});
    case xcp::host::DataType::float32: return read(float{});
    case xcp::host::DataType::float64: return read(double{});
    default: return 0;
  }
}

// The generated model on the executive in lock-step, its measurements read where its A2L says they are.
Recording run_generated(const Example& example, LoggingPlant& plant) {
  auto a2l_text = read_text_file(generated_folder(example.name) + "/" + example.name + ".a2l");
  EXPECT_TRUE(a2l_text.ok());
  auto a2l = xcp::host::read_a2l(a2l_text.value());
  EXPECT_TRUE(a2l.ok()) << a2l.error();
  // The model's signals, not the executive's account that the A2L describes beside them.
  std::vector<xcp::host::Variable> measurements;
  std::copy_if(a2l.value().measurements.begin(), a2l.value().measurements.end(), std::back_inserter(measurements),
               [&](const xcp::host::Variable& measurement) { return !is_executive_account(a2l.value(), measurement); });
  Recording recording;
  for (const xcp::host::Variable& measurement : measurements) {
    for (std::uint32_t element = 0; element < measurement.count; ++element) {
      std::string name = measurement.name;
      std::replace(name.begin(), name.end(), '.', '/');
      recording.names.push_back(measurement.count == 1 ? name : name + "[" + std::to_string(element) + "]");
    }
  }
  recording.columns.resize(recording.names.size());
  hardware::connect(&plant);
  host::LockStepPort port{example.description};
  rt::Executive<host::LockStepPort, 16> executive{example.description, port};
  port.attach(executive);
  EXPECT_EQ(executive.initialize(), rt::TaskTableError::none);
  EXPECT_TRUE(executive.begin());
  const double period_s = example.description.base_period_ns * 1e-9;
  for (std::uint64_t tick = 0; tick < example.ticks; ++tick) {
    if (example.tune_generated) example.tune_generated(tick);
    // The plant raises interrupts by name: the generated task table names each interrupt task after its interrupt.
    plant.advance(static_cast<double>(tick) * period_s, [&](std::string_view interrupt) {
      for (std::size_t task = 0; task < example.description.tasks.size(); ++task) {
        const rt::Task& entry = example.description.tasks[task];
        if (entry.kind == rt::TaskKind::interrupt && entry.name == interrupt) port.raise(task);
      }
    });
    port.advance(1);
    recording.time_s.push_back(static_cast<double>(tick) * period_s);
    std::size_t column = 0;
    for (const xcp::host::Variable& measurement : measurements) {
      const auto* base = static_cast<const std::byte*>(example.signals) + (measurement.address - signals_xcp_address);
      for (std::uint32_t element = 0; element < measurement.count; ++element) {
        recording.columns[column++].push_back(
            decode(measurement.type, base + element * xcp::host::size_of(measurement.type)));
      }
    }
  }
  executive.end();
  hardware::connect(nullptr);
  return recording;
}

// pid_demo's parameters, numbered as in pid_demo.yaml.
namespace pid_demo_parameter {
constexpr std::size_t Kp = 0;
constexpr std::size_t trim = 6;
constexpr std::size_t stall_limit = 7;
constexpr std::size_t halt = 8;
constexpr std::size_t disturbance = 11;
constexpr std::size_t dead_band = 12;
}  // namespace pid_demo_parameter

// thermostat's.
namespace thermostat_parameter {
constexpr std::size_t setpoint = 0;
}  // namespace thermostat_parameter

// tilt_reference's: the referenced controller's parameters, in its order.
namespace tilt_reference_parameter {
constexpr std::size_t Kp = 0;
}  // namespace tilt_reference_parameter

// block_tour's.
namespace block_tour_parameter {
constexpr std::size_t tf_den = 0;
constexpr std::size_t ss_a = 1;
constexpr std::size_t lut_table = 2;
}  // namespace block_tour_parameter

std::vector<Example> examples() {
  std::vector<std::uint16_t> table(4096);
  std::mt19937 random{2026};
  for (std::uint16_t& value : table) value = static_cast<std::uint16_t>(random());
  return {
      {"step_time", step_time::description, &step_time::signals, 1000, {}, {}},
      {"transfer_test", transfer_test::description, &transfer_test::signals, 5000,
       // The master's part: the table, then play; at 3000 the reference page (not playing) for 500 ticks.
       [table](std::uint64_t tick, Interpreter& model) {
         if (tick == 7) {
           for (std::size_t i = 0; i < table.size(); ++i) model.set_parameter(0, i, table[i]);
           model.set_parameter(1, 0, 1);
         }
         if (tick == 3000) model.use_reference_page(true);
         if (tick == 3500) model.use_reference_page(false);
       },
       [table](std::uint64_t tick) {
         if (tick == 7) {
           std::copy(table.begin(), table.end(), transfer_test::parameters.table);
           transfer_test::parameters.playing = true;
         }
         if (tick == 3000)
           transfer_test::parameter_page = reinterpret_cast<const std::uint8_t*>(&transfer_test::reference_parameters);
         if (tick == 3500)
           transfer_test::parameter_page = reinterpret_cast<const std::uint8_t*>(&transfer_test::parameters);
       }},
      {"pid_demo",
       pid_demo::description,
       &pid_demo::signals,
       6000,
       // A calibration session: a gain, the motor logic's dead band and the trim tuned, the operator's stop for 400
       // ticks, the reference page for 500, then a shorter stall limit and a load the motor cannot hold: the stall
       // stops it, then the angle limit.
       [](std::uint64_t tick, Interpreter& model) {
         if (tick == 1000) model.set_parameter(pid_demo_parameter::Kp, 0, 0.03);
         if (tick == 1500) model.set_parameter(pid_demo_parameter::dead_band, 0, 0.002);
         if (tick == 2000) model.set_parameter(pid_demo_parameter::trim, 0, -0.3);
         if (tick == 2600) model.set_parameter(pid_demo_parameter::halt, 0, 1);
         if (tick == 3000) model.set_parameter(pid_demo_parameter::halt, 0, 0);
         if (tick == 3500) model.use_reference_page(true);
         if (tick == 4000) model.use_reference_page(false);
         if (tick == 4500) model.set_parameter(pid_demo_parameter::stall_limit, 0, 0.2);
         if (tick == 4500) model.set_parameter(pid_demo_parameter::disturbance, 0, 800);
       },
       [](std::uint64_t tick) {
         if (tick == 1000) pid_demo::parameters.Kp = 0.03F;
         if (tick == 1500) pid_demo::parameters.dead_band = 0.002F;
         if (tick == 2000) pid_demo::parameters.trim = -0.3F;
         if (tick == 2600) pid_demo::parameters.halt = true;
         if (tick == 3000) pid_demo::parameters.halt = false;
         if (tick == 3500)
           pid_demo::parameter_page = reinterpret_cast<const std::uint8_t*>(&pid_demo::reference_parameters);
         if (tick == 4000) pid_demo::parameter_page = reinterpret_cast<const std::uint8_t*>(&pid_demo::parameters);
         if (tick == 4500) pid_demo::parameters.stall_limit = 0.2F;
         if (tick == 4500) pid_demo::parameters.disturbance = 800.0F;
       },
       {},
       // The motor logic (a Code block) and the safety stops counted by an edge-triggered subsystem.
       {"in1", "in2", "stby", "pwm", "reversals", "stops"}},
      // The thermostat against its heater, a plant model (1 ms) loaded from heater.yaml on each side, its ten ticks
      // between the controller's (10 ms); at 1000 the set point goes up by 2 degrees.
      {"thermostat",
       thermostat::description,
       &thermostat::signals,
       2000,
       [](std::uint64_t tick, Interpreter& model) {
         if (tick == 1000) model.set_parameter(thermostat_parameter::setpoint, 0, 2200);
       },
       [](std::uint64_t tick) {
         if (tick == 1000) thermostat::parameters.setpoint = 2200;
       },
       plant_model("thermostat/heater.yaml"),
       {"heating", "sample"}},
      // The self-balancing robot against the simulated robot, held at 5 degrees until 2 s: every interrupt task
      // runs (the MPU6500's chain, the PWM timer, the hall encoders, the echo, the ADC's DMA, a message from Linux),
      // and the noise is the same on both sides (one seed).
      {"balbot",
       balbot::description,
       &balbot::signals,
       4000,
       {},
       {},
       [] {
         plant::BalbotScenario scenario;
         scenario.release_time_s = 2;
         scenario.ipc_messages.push_back({3, {0, 0, 128, 63, 0, 0, 0, 64, 0, 0, 64, 64}});  // P 1, I 2, D 3
         return std::unique_ptr<plant::Plant>{plant::make_balbot_plant(scenario)};
       },
       {"sensor_ready", "stop", "theta", "y", "wheel_speed_left", "wheel_speed_right", "distance", "battery_voltage",
        "linux_gains[0]", "gains_from", "y_pid", "requests_sent"}},
      // Every block type the other examples leave out, fed by sources; at 1500 the transfer function's a1, the
      // state space's A[1][0] and the middle value of the interpolation table are tuned.
      {"block_tour",
       block_tour::description,
       &block_tour::signals,
       3000,
       [](std::uint64_t tick, Interpreter& model) {
         if (tick == 1500) model.set_parameter(block_tour_parameter::tf_den, 1, -1.5);
         if (tick == 1500) model.set_parameter(block_tour_parameter::ss_a, 2, -0.09);
         if (tick == 1500) model.set_parameter(block_tour_parameter::lut_table, 1, 1.25);
       },
       [](std::uint64_t tick) {
         if (tick == 1500) block_tour::parameters.tf_den[1] = -1.5;
         if (tick == 1500) block_tour::parameters.ss_a[2] = -0.09F;
         if (tick == 1500) block_tour::parameters.lut_table[1] = 1.25F;
       },
       {},
       {"saw_sign",
        "minimum",
        "maximum",
        "quotient",
        "inverse",
        "pulse",
        "late",
        "step",
        "square",
        "word",
        "frame_big[0]",
        "frame_big[5]",
        "frame_little[0]",
        "frame_little[10]",
        "word_back",
        "rate_back",
        "count_back",
        "halves[0]",
        "above",
        "under[0]",
        "under[1]",
        "zoned",
        "shaped",
        "bent",
        "stepped",
        "floored",
        "raised",
        "rate",
        "filtered",
        "oscillator_y[0]",
        "oscillator_y[1]",
        "oscillator_mean",
        "smoothed",
        "tracked[0]",
        "tracked[1]",
        "feedback",
        "estimate[0]",
        "estimate[1]",
        "error",
        "command",
        "position"}},
      // A model reference: the PI controller of tilt_controller.yaml inside a model that closes its loop, its gain
      // (the referenced model's parameter, now the model's) tuned at 400; its Inport and Outport are the plant's.
      {"tilt_reference",
       tilt_reference::description,
       &tilt_reference::signals,
       800,
       [](std::uint64_t tick, Interpreter& model) {
         if (tick == 400) model.set_parameter(tilt_reference_parameter::Kp, 0, 3);
       },
       [](std::uint64_t tick) {
         if (tick == 400) tilt_reference::parameters.Kp = 3;
       },
       {},
       {"tilt", "duty_command", "controller/integral"}},
  };
}

class BackToBack : public testing::TestWithParam<std::size_t> {};

TEST_P(BackToBack, GeneratedCodeComputesWhatTheInterpreterComputes) {
  const Example example = examples()[GetParam()];
  auto model = load_model(example_file(example.name));
  ASSERT_TRUE(model.ok()) << model.error();
  const ProgramBuild build = build_program(model.value());
  ASSERT_TRUE(build.program.has_value());
  LoggingPlant interpreted_plant{example.plant};
  SimulationOptions options;
  options.duration_s = static_cast<double>(example.ticks - 1) * model.value().base_period_us * 1e-6;
  options.before_tick = example.tune_interpreted;
  options.record_plant = false;  // the generated run records the model's measurements only
  auto simulated = simulate(*build.program, interpreted_plant, options);
  ASSERT_TRUE(simulated.ok()) << simulated.error();
  const Recording& expected = simulated.value().recording;

  LoggingPlant generated_plant{example.plant};
  const Recording generated = run_generated(example, generated_plant);
  ASSERT_EQ(generated.names, expected.names);
  ASSERT_EQ(generated.time_s.size(), expected.time_s.size());
  for (std::size_t column = 0; column < expected.columns.size(); ++column) {
    for (std::size_t row = 0; row < expected.time_s.size(); ++row) {
      const double a = expected.columns[column][row];
      const double b = generated.columns[column][row];
      ASSERT_EQ(std::memcmp(&a, &b, sizeof(double)), 0)
          << expected.names[column] << " at tick " << row << ": interpreter " << a << ", generated " << b;
    }
  }
  EXPECT_EQ(generated_plant.log, interpreted_plant.log);
  // Something happened worth comparing: every example's measurements change over the run.
  bool changes = false;
  for (const auto& column : expected.columns)
    changes = changes || std::adjacent_find(column.begin(), column.end(), std::not_equal_to<>{}) != column.end();
  EXPECT_TRUE(changes);
  for (const std::string& name : example.changing) {
    const auto found = std::find(expected.names.begin(), expected.names.end(), name);
    ASSERT_NE(found, expected.names.end()) << name << " is not measured";
    const auto& column = expected.columns[static_cast<std::size_t>(found - expected.names.begin())];
    EXPECT_NE(std::adjacent_find(column.begin(), column.end(), std::not_equal_to<>{}), column.end())
        << name << " stays " << column.front();
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, BackToBack, testing::Range<std::size_t>(0, examples().size()),
                         [](const testing::TestParamInfo<std::size_t>& parameter) {
                           return examples()[parameter.param].name;
                         });

}  // namespace
}  // namespace duet::model
