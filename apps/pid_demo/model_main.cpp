// The pid_demo model as duet gen generates it from pid_demo.yaml (generated/), on the executive on the emulated
// Cortex-M4 in multitasking mode: 1000 base ticks of the 1 ms loop and 100 of the 10 ms supervision, without an
// overrun, ending bit for bit where duet sim ends on the PC. Then the benchmark of issue #7 for a real controller:
// instructions per step of the generated steps against the same computation written by hand below (the same float
// operations in the same order, the same globals for the measurable signals, the same LED write), each measured as
// the instructions a base tick costs above an empty model's (QEMU -icount shift=0: exact counts).

#include <bit>
#include <cmath>
#include <cstdint>

#include "duet/base/text_buffer.hpp"
#include "duet/cortex_m/board_hooks.hpp"
#include "duet/cortex_m/interrupts.hpp"
#include "duet/cortex_m/registers.hpp"
#include "duet/mps2_an386/board.hpp"
#include "duet/mps2_an386/executive_port.hpp"
#include "duet/rt/executive.hpp"
#include "pid_demo.hpp"
#include "tick_overhead.hpp"

// What one would write by hand for the same controller and plant: the calibration in one structure, the measurable
// signals as globals, the state as file-scope variables, and one release countdown for the values the 1 ms loop and
// the 10 ms supervision exchange.
namespace hand_written {

struct Calibration {
  float kp;
  float ki;
  float kd;
  float n;
  float profile[10];
  float angle_limit;
  float trim;
  float stall_limit;
  bool halt;
  float a[2][2];
  float b[2][2];
  float disturbance;
  float dead_band;
};
Calibration calibration{
    .kp = 0.0196F,
    .ki = 0.05F,
    .kd = 0.0187F,
    .n = 28.234F,
    .profile = {0.0F, 0.0F, 1.0F, 1.0F, 0.0F, 0.0F, -1.0F, -1.0F, 0.5F, 0.0F},
    .angle_limit = 20.0F,
    .trim = 0.2F,
    .stall_limit = 0.5F,
    .halt = false,
    .a = {{1.0F, 0.0009994951699737688F}, {0.0F, 0.9989905098783265F}},
    .b = {{0.00037087512818177184F, 4.998317091398542e-07F}, {0.7416254161205363F, 0.0009994951699737688F}},
    .disturbance = -2.0F,
    .dead_band = 0.01F};

// The measurable signals.
float reference;
float setpoint;
float error;
bool stop;
float duty;
std::uint16_t compare;
bool in1;
bool in2;
bool stby;
float pwm;
std::uint32_t reversals;
std::uint16_t stops;
float theta;
float rate;
float offset;
float iae;
float stall;

namespace {

constexpr float period_s = 0.001F;
constexpr float supervision_period_s = 0.01F;

// The 1 ms loop.
std::uint32_t count;
float integrator;
float filter;
float x[2];
std::int8_t heading;  // the motor logic's last direction
bool stop_before;     // the stop in the step before, for its rising edge
std::uint16_t stop_count;
// Between the loop and the supervision: the loop takes and hands over values at the supervision's release ticks.
std::uint32_t ticks_to_release;
float error_latched;
float duty_latched;
bool stop_latched;
float offset_produced;
float offset_held;
bool stop_request_produced;
bool stop_request_held;
// The 10 ms supervision.
float iae_integral;
float stall_integral;
float trim_now;

float limit(float value, float lower, float upper) {
  if (value > upper) return upper;
  if (value < lower) return lower;
  return value;
}

}  // namespace

void reset() {
  count = 0;
  integrator = 0.0F;
  filter = 0.0F;
  x[0] = 0.0F;
  x[1] = 0.0F;
  heading = 0;
  reversals = 0;
  stop_before = false;
  stop_count = 1;
  stops = 0;
  ticks_to_release = 0;
  error_latched = 0.0F;
  duty_latched = 0.0F;
  stop_latched = false;
  offset_produced = 0.0F;
  offset_held = 0.0F;
  stop_request_produced = false;
  stop_request_held = false;
  iae_integral = 0.0F;
  stall_integral = 0.0F;
  trim_now = 0.0F;
}

void step_1ms() {
  const Calibration& c = calibration;
  // The reference: the profile, one element per 500 steps.
  auto index = static_cast<std::uint32_t>(static_cast<float>(count) * 0.002F);
  if (index > 9U) index = 9U;
  reference = c.profile[index];
  // The plant's state and what it does by itself.
  const float x0 = x[0];
  const float x1 = x[1];
  const float a_x0 = c.a[0][0] * x0 + c.a[0][1] * x1;
  const float a_x1 = c.a[1][0] * x0 + c.a[1][1] * x1;
  theta = x0;
  rate = x1;
  const bool too_far = std::fabs(theta) > c.angle_limit;
  // The supervision's values, taken at its release ticks.
  const bool release = ticks_to_release == 0;
  ticks_to_release = release ? 9U : ticks_to_release - 1U;
  if (release) {
    offset_held = offset_produced;
    stop_request_held = stop_request_produced;
  }
  offset = offset_held;
  setpoint = reference + offset;
  error = setpoint - theta;
  // The PID, parallel, forward Euler, its derivative filtered.
  const float derivative = c.n * (c.kd * error - filter);
  const float pid_output = limit(c.kp * error + integrator + derivative, -1.0F, 1.0F);
  stop = too_far || stop_request_held;
  duty = limit(stop ? 0.0F : pid_output, -1.0F, 1.0F);
  compare = static_cast<std::uint16_t>((duty + 1.0F) * 2100.0F);
  volatile std::uint32_t& leds = duet::cortex_m::register32(duet::mps2_an386::leds_register);
  leds = stop ? (leds | 1U) : (leds & ~1U);
  // The motor logic: the H-bridge's pins (TB6612FNG) and its PWM in percent, the reversals counted; the pins on LEDs.
  std::int8_t direction = 0;
  if (duty > c.dead_band) {
    direction = 1;
  } else if (duty < -c.dead_band) {
    direction = -1;
  }
  if (stop) direction = 0;
  stby = !stop;
  in1 = !stop && direction >= 0;
  in2 = !stop && direction <= 0;
  if (direction > 0) {
    pwm = duty * 100.0F;
  } else if (direction < 0) {
    pwm = duty * -100.0F;
  } else {
    pwm = 0.0F;
  }
  if (direction != 0) {
    if (heading != 0 && heading != direction) ++reversals;
    heading = direction;
  }
  leds = in1 ? (leds | 2U) : (leds & ~2U);
  leds = in2 ? (leds | 4U) : (leds & ~4U);
  leds = stby ? (leds | 8U) : (leds & ~8U);
  // The safety stops, counted at the stop's rising edges.
  if (stop && !stop_before) {
    stops = stop_count;
    ++stop_count;  // after 65535, 0: the Counter's limit
  }
  stop_before = stop;
  // The plant's step.
  const float x_next0 = a_x0 + (c.b[0][0] * duty + c.b[0][1] * c.disturbance);
  const float x_next1 = a_x1 + (c.b[1][0] * duty + c.b[1][1] * c.disturbance);
  count = count >= 4999U ? 0U : count + 1U;
  filter = filter + period_s * derivative;
  integrator = integrator + period_s * (c.ki * error);
  x[0] = x_next0;
  x[1] = x_next1;
  // For the supervision.
  if (release) {
    error_latched = error;
    duty_latched = duty;
    stop_latched = stop;
  }
}

void step_10ms() {
  const Calibration& c = calibration;
  // The absolute error, integrated while the loop runs.
  const bool running = !stop_latched;
  float error_magnitude = 0.0F;
  if (running) {
    error_magnitude = std::fabs(error_latched);
    iae = iae_integral;
  }
  // Stop when the duty stays saturated: 1 s/s up while it is, down while it is not.
  const float stall_change = std::fabs(duty_latched) >= 0.98F ? 1.0F : -1.0F;
  stall = stall_integral;
  stop_request_produced = stall >= c.stall_limit || c.halt;
  // The trim, ramped in at 0.01 degrees per step.
  const float trim_before = trim_now;
  const float trim_next = trim_before + limit(c.trim - trim_before, -0.01F, 0.01F);
  offset_produced = trim_next;
  if (running) iae_integral = iae_integral + supervision_period_s * error_magnitude;
  stall_integral = limit(stall_integral + supervision_period_s * stall_change, 0.0F, 1.0F);
  trim_now = trim_next;
}

}  // namespace hand_written

namespace {

namespace board = duet::mps2_an386;

using ModelExecutive = duet::rt::Executive<duet::bench::CountingPort, 2>;
ModelExecutive* model_executive = nullptr;

void empty_step() {}

// Both steps of one base tick, as single-tasking runs them.
void generated_tick(std::uint32_t tick) {
  pid_demo::step_rate_1();
  if (tick % 10U == 0U) pid_demo::step_rate_10();
}
void hand_written_tick(std::uint32_t tick) {
  hand_written::step_1ms();
  if (tick % 10U == 0U) hand_written::step_10ms();
}

// What duet sim computes on the PC for the same 1000 ticks (the last row of `duet sim apps/pid_demo/pid_demo.yaml
// --duration 0.999`), as float bits: the firmware must end exactly there.
constexpr std::uint32_t host_theta = 0x3e212229;  // 0.15735687
constexpr std::uint32_t host_rate = 0x3c9dccf0;   // 0.019262761
constexpr std::uint32_t host_duty = 0x3b3a8b1f;   // 0.0028464270
constexpr std::uint32_t host_iae = 0x3d3e5670;    // 0.046469152
constexpr std::uint16_t host_compare = 2105;
constexpr std::uint32_t host_pwm = 0x00000000;  // 0: the duty is inside the dead band, the motor brakes
constexpr bool host_in1 = true;
constexpr bool host_in2 = true;
constexpr bool host_stby = true;
constexpr std::uint32_t host_reversals = 0;
constexpr std::uint16_t host_stops = 0;

bool finite(float value) { return value - value == 0.0F; }

void write_hundredths(duet::TextBuffer<200>& line, std::uint64_t hundredths) {
  line.append(hundredths / 100U).append('.').append(hundredths % 100U < 10U ? "0" : "").append(hundredths % 100U);
}

// value in millionths, rounded toward zero: enough to read, the bits say the rest.
void write_micro(duet::TextBuffer<200>& line, float value) {
  const float magnitude = value < 0.0F ? -value : value;
  const auto micro = static_cast<std::uint32_t>(magnitude * 1e6F);
  line.append(value < 0.0F ? "-" : "").append(micro / 1'000'000U).append('.');
  const std::uint32_t fraction = micro % 1'000'000U;
  for (std::uint32_t digit = 100'000U; digit > 1U && fraction < digit; digit /= 10U) line.append('0');
  line.append(fraction);
}

void write_float(duet::TextBuffer<200>& line, const char* name, float value) {
  line.append(name).append(' ');
  write_micro(line, value);
  line.append(" (").append_hex(std::bit_cast<std::uint32_t>(value)).append(')');
}

constexpr std::uint32_t ticks = 1000;
constexpr std::uint32_t bench_period_ns = 10'000;
constexpr std::uint32_t bench_ticks = 10'000;

}  // namespace

extern "C" void TIMER0_IRQHandler() {
  board::ExecutivePort::acknowledge_base_tick();
  if (model_executive != nullptr) {
    model_executive->on_base_tick();
  } else if (duet::bench::running_executive != nullptr) {
    duet::bench::running_executive->on_base_tick();
  }
}
extern "C" void Software1_IRQHandler() {
  if (model_executive != nullptr) model_executive->on_rate_interrupt(1);
}

int main() {
  board::initialize();
  duet::cortex_m::enable_interrupts();

  // The generated model as the executive runs it, the supervision preempted by the loop.
  duet::rt::ModelDescription model = pid_demo::description;
  model.final_tick = ticks;
  model.tasking_mode = duet::rt::TaskingMode::multi;
  duet::bench::CountingPort port;
  ModelExecutive executive{model, port};
  model_executive = &executive;
  const bool ran = board::run_model(executive, model);
  model_executive = nullptr;
  const duet::rt::TaskStatistics& loop = executive.statistics(0);
  const duet::rt::TaskStatistics& supervision = executive.statistics(1);
  const pid_demo::Signals& s = pid_demo::signals;
  const auto led_on = [](unsigned number) {
    return (duet::cortex_m::register32(board::leds_register) & (1U << number)) != 0;
  };
  const bool led = led_on(0U);
  duet::TextBuffer<200> line;
  line.append("generated pid_demo: ").append(loop.activations).append(" loop steps, ").append(loop.overruns);
  line.append(" overruns; ").append(supervision.activations).append(" supervision steps, ");
  line.append(supervision.overruns).append(" overruns\n");
  duet::cortex_m::console_write(line.view());
  line.clear();
  write_float(line, "theta", s.theta);
  line.append(", ");
  write_float(line, "rate", s.rate);
  line.append(", ");
  write_float(line, "duty", s.duty);
  line.append('\n');
  write_float(line, "iae", s.iae);
  line.append(", compare ").append(s.compare).append(", stop ").append(s.stop).append(", LED0 ");
  line.append(led ? "on" : "off").append('\n');
  duet::cortex_m::console_write(line.view());
  line.clear();
  write_float(line, "pwm", s.pwm);
  line.append(", IN1 ").append(s.in1).append(", IN2 ").append(s.in2).append(", STBY ").append(s.stby);
  line.append(", reversals ").append(s.reversals).append(", stops ").append(s.stops).append('\n');
  duet::cortex_m::console_write(line.view());
  const bool as_on_the_pc =
      std::bit_cast<std::uint32_t>(s.theta) == host_theta && std::bit_cast<std::uint32_t>(s.rate) == host_rate &&
      std::bit_cast<std::uint32_t>(s.duty) == host_duty && std::bit_cast<std::uint32_t>(s.iae) == host_iae &&
      s.compare == host_compare && std::bit_cast<std::uint32_t>(s.pwm) == host_pwm && s.in1 == host_in1 &&
      s.in2 == host_in2 && s.stby == host_stby && s.reversals == host_reversals && s.stops == host_stops;
  const bool sane = finite(s.theta) && finite(s.rate) && finite(s.iae) && s.duty >= -1.0F && s.duty <= 1.0F &&
                    s.compare <= 4200U && !s.stop && led == s.stop && led_on(1U) == s.in1 && led_on(2U) == s.in2 &&
                    led_on(3U) == s.stby;
  const bool model_ok = ran && loop.activations == ticks && supervision.activations == ticks / 10U &&
                        loop.overruns == 0 && supervision.overruns == 0 && as_on_the_pc && sane;
  line.clear();
  line.append(as_on_the_pc ? "bit for bit as duet sim on the PC" : "NOT as duet sim on the PC (expected theta ");
  if (!as_on_the_pc) line.append_hex(host_theta).append(", iae ").append_hex(host_iae).append(')');
  line.append(model_ok ? "; model check passed\n" : "; model check FAILED\n");
  duet::cortex_m::console_write(line.view());

  // The hand-written steps compute what the generated ones do: every measurable signal compared after each tick,
  // for 1000 ticks from the start, then 1000 more with the operator's stop for 200 ticks (the motor logic's standby
  // and the counted stops) and a smaller dead band (more reversals).
  const auto same_signals = [&s] {
    return s.reference == hand_written::reference && s.setpoint == hand_written::setpoint &&
           s.error == hand_written::error && s.stop == hand_written::stop && s.duty == hand_written::duty &&
           s.compare == hand_written::compare && s.in1 == hand_written::in1 && s.in2 == hand_written::in2 &&
           s.stby == hand_written::stby && s.pwm == hand_written::pwm && s.reversals == hand_written::reversals &&
           s.stops == hand_written::stops && s.theta == hand_written::theta && s.rate == hand_written::rate &&
           s.offset == hand_written::offset && s.iae == hand_written::iae && s.stall == hand_written::stall;
  };
  pid_demo::initialize();
  hand_written::reset();
  bool same = true;
  for (std::uint32_t tick = 0; tick < 2U * ticks; ++tick) {
    if (tick == 1200U || tick == 1400U) {
      pid_demo::parameters.halt = tick == 1200U;
      hand_written::calibration.halt = tick == 1200U;
    }
    if (tick == 1500U || tick == 2U * ticks - 1U) {
      pid_demo::parameters.dead_band = tick == 1500U ? 0.002F : 0.01F;
      hand_written::calibration.dead_band = tick == 1500U ? 0.002F : 0.01F;
    }
    generated_tick(tick);
    hand_written_tick(tick);
    same = same && same_signals();
  }
  line.clear();
  line.append("after the stop: ").append(s.stops).append(" stops, ").append(s.reversals).append(" reversals, ");
  line.append("LED1..3 (IN1, IN2, STBY) ").append(led_on(1U) ? "on" : "off").append(' ');
  line.append(led_on(2U) ? "on" : "off").append(' ').append(led_on(3U) ? "on" : "off").append('\n');
  duet::cortex_m::console_write(line.view());
  same =
      same && s.stops == 1U && s.reversals > 0U && led_on(1U) == s.in1 && led_on(2U) == s.in2 && led_on(3U) == s.stby;
  line.clear();
  line.append(same ? "hand-written steps compute the same signals\n" : "hand-written steps DIFFER from generated\n");
  duet::cortex_m::console_write(line.view());

  // The benchmark: 10,000 ticks of 10 us each way, minus an empty model's tick.
  const std::uint64_t empty =
      duet::bench::hundredths_of_instructions_per_tick(bench_period_ns, bench_ticks, empty_step);
  const std::uint64_t generated_loop =
      duet::bench::hundredths_of_instructions_per_tick(bench_period_ns, bench_ticks, pid_demo::step_rate_1) - empty;
  const std::uint64_t hand_loop =
      duet::bench::hundredths_of_instructions_per_tick(bench_period_ns, bench_ticks, hand_written::step_1ms) - empty;
  const std::uint64_t generated_supervision =
      duet::bench::hundredths_of_instructions_per_tick(bench_period_ns, bench_ticks, pid_demo::step_rate_10) - empty;
  const std::uint64_t hand_supervision =
      duet::bench::hundredths_of_instructions_per_tick(bench_period_ns, bench_ticks, hand_written::step_10ms) - empty;
  const auto report = [&line](const char* what, std::uint64_t generated, std::uint64_t hand) {
    line.clear();
    line.append("instructions per ").append(what).append(": generated ");
    write_hundredths(line, generated);
    line.append(", hand-written ");
    write_hundredths(line, hand);
    line.append(", ratio ");
    const std::uint64_t ratio = hand == 0 ? 0 : generated * 100U / hand;
    write_hundredths(line, ratio);
    line.append('\n');
    duet::cortex_m::console_write(line.view());
    return ratio;
  };
  const std::uint64_t loop_ratio = report("1 ms step", generated_loop, hand_loop);
  report("10 ms step", generated_supervision, hand_supervision);
  report("10 ms of both", 10U * generated_loop + generated_supervision, 10U * hand_loop + hand_supervision);
  line.clear();
  line.append("target: the 1 ms step's ratio <= 1.10: ").append(loop_ratio <= 110U ? "met\n" : "not met\n");
  duet::cortex_m::console_write(line.view());
  return model_ok && same && loop_ratio <= 110U ? 0 : 1;
}
