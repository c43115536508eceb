#include "duet/plant/balbot/balbot_plant.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "balbot_simulation.hpp"

namespace duet::plant {
namespace {

using Motor = BalbotSimulation::Motor;
using Pin = BalbotSimulation::Pin;
using Capture = BalbotSimulation::Capture;

// The resources of the robot's hardware blocks (thesis tables 5.3-5.7).
enum class Resource {
  right_duty,     // pwm:TIM1/3   PWMA
  left_duty,      // pwm:TIM1/4   PWMB
  right_in1,      // gpio:PE10    AIN1 (MTRR_P)
  right_in2,      // gpio:PD14    AIN2 (MTRR_N)
  left_in1,       // gpio:PE9     BIN1 (MTRL_P)
  left_in2,       // gpio:PD1     BIN2 (MTRL_N)
  standby,        // gpio:PA12    STBY
  trigger,        // gpio:PE11    TRIG0
  spi,            // spi:SPI5     MPU6500
  adc,            // adc:ADC1/6   battery divider
  ipc,            // ipc:app      the Linux side
  mpu_int,        // gpio:PE8     MPU_INT
  exti,           // exti:EXTI8   MPU_INT
  left_capture,   // capture:TIM2/1  left hall A
  left_b,         // gpio:PH6        left hall B
  right_capture,  // capture:TIM4/4  right hall A
  right_b,        // gpio:PG3        right hall B
  echo_capture,   // capture:TIM5/2  ECHO0
  unknown,
};

// By length and the last two characters, which tell the names apart, then one comparison to be sure.
Resource resource_of(std::string_view name) {
  if (name.size() < 7) return Resource::unknown;
  const auto key = [](char a, char b) {
    return static_cast<unsigned>(static_cast<unsigned char>(a)) << 8U | static_cast<unsigned char>(b);
  };
  const unsigned last = key(name[name.size() - 2], name[name.size() - 1]);
  const auto is = [&name](std::string_view full, Resource resource) {
    return name == full ? resource : Resource::unknown;
  };
  switch (name.size()) {
    case 7: return is("ipc:app", Resource::ipc);
    case 8:
      switch (last) {
        case key('E', '9'): return is("gpio:PE9", Resource::left_in1);
        case key('D', '1'): return is("gpio:PD1", Resource::left_in2);
        case key('I', '5'): return is("spi:SPI5", Resource::spi);
        case key('E', '8'): return is("gpio:PE8", Resource::mpu_int);
        case key('H', '6'): return is("gpio:PH6", Resource::left_b);
        case key('G', '3'): return is("gpio:PG3", Resource::right_b);
        default: return Resource::unknown;
      }
    case 9:
      switch (last) {
        case key('1', '0'): return is("gpio:PE10", Resource::right_in1);
        case key('1', '4'): return is("gpio:PD14", Resource::right_in2);
        case key('1', '2'): return is("gpio:PA12", Resource::standby);
        case key('1', '1'): return is("gpio:PE11", Resource::trigger);
        default: return Resource::unknown;
      }
    case 10:
      switch (last) {
        case key('/', '3'): return is("pwm:TIM1/3", Resource::right_duty);
        case key('/', '4'): return is("pwm:TIM1/4", Resource::left_duty);
        case key('/', '6'): return is("adc:ADC1/6", Resource::adc);
        case key('I', '8'): return is("exti:EXTI8", Resource::exti);
        default: return Resource::unknown;
      }
    case 14:
      switch (last) {
        case key('/', '1'): return is("capture:TIM2/1", Resource::left_capture);
        case key('/', '4'): return is("capture:TIM4/4", Resource::right_capture);
        case key('/', '2'): return is("capture:TIM5/2", Resource::echo_capture);
        default: return Resource::unknown;
      }
    default: return Resource::unknown;
  }
}

std::optional<Pin> pin_of(Resource resource) {
  switch (resource) {
    case Resource::right_in1: return Pin::right_in1;
    case Resource::right_in2: return Pin::right_in2;
    case Resource::left_in1: return Pin::left_in1;
    case Resource::left_in2: return Pin::left_in2;
    case Resource::standby: return Pin::standby;
    case Resource::trigger: return Pin::trigger;
    default: return std::nullopt;
  }
}

double first(std::span<const double> values) { return values.empty() ? 0.0 : values[0]; }

}  // namespace

BalbotPlant::BalbotPlant(const BalbotScenario& scenario, const BalbotParameters& parameters)
    : simulation_(std::make_unique<BalbotSimulation>(scenario, parameters)) {}

BalbotPlant::~BalbotPlant() = default;

void BalbotPlant::advance(double time_s, const RaiseInterrupt& raise) {
  simulation_->advance(std::llround(std::max(time_s, 0.0) * 1e9), raise);
}

void BalbotPlant::write(std::string_view resource, std::span<const double> values) {
  const Resource which = resource_of(resource);
  if (const std::optional<Pin> pin = pin_of(which)) {
    simulation_->set_pin(*pin, first(values) > 0.5);
    return;
  }
  switch (which) {
    case Resource::right_duty: simulation_->set_duty(Motor::right, first(values)); return;
    case Resource::left_duty: simulation_->set_duty(Motor::left, first(values)); return;
    case Resource::spi: simulation_->spi_transaction(values); return;
    case Resource::adc: simulation_->start_adc(first(values)); return;
    case Resource::ipc: simulation_->send_to_linux(values); return;
    case Resource::unknown: simulation_->note_unknown(resource); return;
    default: return;  // an input of the robot: writing it changes nothing
  }
}

void BalbotPlant::read(std::string_view resource, std::span<double> values) {
  std::fill(values.begin(), values.end(), 0.0);
  const Resource which = resource_of(resource);
  const auto level = [&values](bool high) {
    if (!values.empty()) values[0] = high ? 1.0 : 0.0;
  };
  if (const std::optional<Pin> pin = pin_of(which)) {
    level(simulation_->pin(*pin));
    return;
  }
  switch (which) {
    case Resource::right_duty:
    case Resource::left_duty:
      if (!values.empty())
        values[0] = simulation_->duty_percent(which == Resource::left_duty ? Motor::left : Motor::right);
      return;
    case Resource::spi: simulation_->spi_received(values); return;
    case Resource::adc: simulation_->adc_results(values); return;
    case Resource::ipc: simulation_->message_from_linux(values); return;
    case Resource::mpu_int:
    case Resource::exti: level(simulation_->mpu_int_high()); return;
    case Resource::left_capture: simulation_->capture(Capture::left_hall, values); return;
    case Resource::right_capture: simulation_->capture(Capture::right_hall, values); return;
    case Resource::echo_capture: simulation_->capture(Capture::echo, values); return;
    case Resource::left_b: level(simulation_->hall_b_high(Motor::left)); return;
    case Resource::right_b: level(simulation_->hall_b_high(Motor::right)); return;
    case Resource::unknown: simulation_->note_unknown(resource); return;
    default: return;
  }
}

BalbotTruth BalbotPlant::truth() const { return simulation_->truth(); }
std::span<const std::uint8_t> BalbotPlant::message_to_linux() const { return simulation_->message_to_linux(); }
const std::vector<std::string>& BalbotPlant::unknown_resources() const { return simulation_->unknown_resources(); }
std::uint64_t BalbotPlant::refused_spi_transactions() const { return simulation_->refused_spi_transactions(); }

namespace {

// A truth column's unit, from its name's ending.
std::string unit_of(std::string_view name) {
  constexpr std::pair<std::string_view, std::string_view> endings[] = {
      {"_deg_s", "deg/s"}, {"_deg", "deg"}, {"_m_s", "m/s"}, {"_rev_s", "rev/s"},
      {"_m", "m"},         {"_v", "V"},     {"_a", "A"},     {"_n", "N"}};
  for (const auto& [ending, unit] : endings) {
    if (name.ends_with(ending)) return std::string{unit};
  }
  return {};
}

}  // namespace

std::vector<Plant::Observable> BalbotPlant::observables() const {
  std::vector<Observable> result;
  for (const std::string_view name : BalbotTruth::names()) {
    if (name != "time_s") result.push_back({std::string{name}, unit_of(name)});
  }
  return result;
}

void BalbotPlant::observe(std::span<double> values) const {
  const auto all = truth().values();
  std::size_t at = 0;
  for (std::size_t k = 0; k < BalbotTruth::count && at < values.size(); ++k) {
    if (BalbotTruth::names()[k] != "time_s") values[at++] = all[k];
  }
}

std::vector<DisturbanceKind> BalbotPlant::disturbances() const {
  return {
      {"push",
       "a horizontal force at the body's centre of mass, + forward",
       {{"force_n", "N", -50, 50, 5}, {"duration_s", "s", 0.001, 1, 0.05}}},
      {"duty_pulse",
       "added to both motors' duty, as the thesis' disturbance pulse z1",
       {{"duty", "", -1, 1, 1}, {"duration_s", "s", 0.001, 1, 0.001}}},
      {"restart", "picked up, put back at the scenario's tilt within 1 s, held and let go as the scenario does", {}}};
}

void BalbotPlant::disturb(const Disturbance& disturbance, double time_s) {
  const auto argument = [&disturbance](std::size_t index) {
    return index < disturbance.arguments.size() ? disturbance.arguments[index] : 0.0;
  };
  if (disturbance.name == "push") {
    simulation_->push({.time_s = time_s, .force_n = argument(0), .duration_s = argument(1)});
  } else if (disturbance.name == "duty_pulse") {
    simulation_->disturb_duty({.time_s = time_s, .duty = argument(0), .duration_s = argument(1)});
  } else if (disturbance.name == "restart") {
    simulation_->restart(time_s);
  }
}

std::unique_ptr<BalbotPlant> make_balbot_plant(std::uint64_t seed) {
  BalbotScenario scenario;
  scenario.seed = seed;
  return std::make_unique<BalbotPlant>(scenario);
}

std::unique_ptr<BalbotPlant> make_balbot_plant(const BalbotScenario& scenario) {
  return std::make_unique<BalbotPlant>(scenario);
}

}  // namespace duet::plant
