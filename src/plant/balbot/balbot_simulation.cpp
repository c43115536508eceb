#include "balbot_simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "fast_math.hpp"

namespace duet::plant {
namespace {

using balbot::MechanicalState;
using balbot::Nanoseconds;
using balbot::never;

constexpr Nanoseconds longest_step = 1'000'000;  // integration steps of at most 1 ms
constexpr Nanoseconds pwm_period = 500'000;      // TIM1, thesis task 4
// A restart turns the body back to the scenario's tilt in a second: as a hand does, and slowly enough for the
// firmware's Kalman filter, which follows the tilt through the gyroscope, to follow it (README.md, "Restart").
constexpr Nanoseconds carry_time = 1'000'000'000;
constexpr double degrees_per_radian = 180 / std::numbers::pi;

Nanoseconds nanoseconds(double seconds) { return std::llround(std::max(seconds, 0.0) * 1e9); }
double seconds(Nanoseconds time) { return static_cast<double>(time) * 1e-9; }
std::uint8_t byte_of(double value) { return value >= 0 && value <= 255 ? static_cast<std::uint8_t>(value) : 0; }

bool same(const balbot::Drive& a, const balbot::Drive& b) {
  return a.left.connected == b.left.connected && a.left.drive == b.left.drive &&
         a.right.connected == b.right.connected && a.right.drive == b.right.drive && a.push_force_n == b.push_force_n &&
         a.held == b.held;
}

MechanicalState initial_state(const BalbotScenario& scenario, const BalbotParameters& parameters) {
  MechanicalState s;
  s.theta = scenario.initial_tilt_deg / degrees_per_radian;
  if (scenario.rig == BalbotRig::wheels_driven) {
    s.v = 2 * std::numbers::pi * parameters.wheel_radius_m * scenario.driven_wheel_rev_s;
  }
  return s;
}

}  // namespace

BalbotSimulation::BalbotSimulation(const BalbotScenario& scenario, const BalbotParameters& parameters)
    : parameters_(parameters),
      rig_(scenario.rig),
      sensor_height_(scenario.sensor_mount_height_m),
      wall_distance_(scenario.wall_distance_m),
      mechanics_(parameters, scenario.rig, scenario.battery_v),
      imu_noise_(scenario.seed),
      adc_noise_(scenario.seed ^ 0x9E3779B97F4A7C15ULL),  // apart, so that reading the battery leaves the IMU's noise
      committed_(initial_state(scenario, parameters)),
      current_(committed_),
      scenario_(scenario),
      initial_(committed_),
      next_pwm_period_(pwm_period),
      halls_{balbot::HallEncoder{+1, parameters.hall_edges_per_wheel_turn, 0.0},
             balbot::HallEncoder{-1, parameters.hall_edges_per_wheel_turn, 0.0}},
      mpu_(parameters, scenario.noise ? &imu_noise_ : nullptr),
      ultrasonic_(parameters),
      adc_(parameters, scenario.noise ? &adc_noise_ : nullptr) {
  plan_scenario(0);
  for (const BalbotIpcMessage& message : scenario.ipc_messages) {
    const std::size_t size = std::min(message.bytes.size(), most_message_bytes);
    messages_.push_back({nanoseconds(message.time_s),
                         {message.bytes.begin(), message.bytes.begin() + static_cast<std::ptrdiff_t>(size)}});
  }
  std::stable_sort(messages_.begin(), messages_.end(),
                   [](const Message& a, const Message& b) { return a.time < b.time; });
  to_linux_.reserve(most_message_bytes);
  from_linux_.reserve(most_message_bytes);
  for (balbot::HallEncoder& hall : halls_) hall.start(mechanics_.wheel_angle(committed_));
  update_drive(true, true);
}

// ---- Time ------------------------------------------------------------------------------------------------------

void BalbotSimulation::advance(Nanoseconds target, const RaiseInterrupt& raise) {
  target = std::max(target, now_);
  raise_ = &raise;
  for (;;) {
    ensure_segment(target);
    const Next next = next_event();
    if (next.source != Source::none) {
      move_to(next.time);
      handle(next);
      continue;
    }
    commit_segment();
    if (committed_time_ >= target) break;
  }
  raise_ = nullptr;
}

void BalbotSimulation::ensure_segment(Nanoseconds target) {
  if (segment_valid_) return;
  // Segments end at the PWM timer's interrupt too: the firmware sets the duty there, and a drive that changes inside
  // a segment throws away the part integrated beyond it.
  segment_end_time_ = std::min({target, committed_time_ + longest_step, std::max(next_pwm_period_, committed_time_)});
  if (carried()) segment_end_time_ = std::min(segment_end_time_, carry_end_);  // the hand lets go there
  if (segment_end_time_ > committed_time_) {
    const double h = seconds(segment_end_time_ - committed_time_);
    segment_end_ = moved_to(segment_end_time_);
    segment_ = balbot::Segment{committed_, segment_end_, h, parameters_.wheel_radius_m};
  } else {
    segment_end_ = committed_;
  }
  segment_valid_ = true;
  plan_halls();
}

void BalbotSimulation::plan_halls() {
  const Nanoseconds length = segment_end_time_ - committed_time_;
  if (length <= 0) return;
  turns_ = balbot::turning_points(segment_.wheel);
  for (balbot::HallEncoder& hall : halls_) hall.plan(segment_.wheel, turns_, committed_time_, length, 0.0);
}

void BalbotSimulation::commit_segment() {
  convert_until(segment_end_time_, true);
  for (balbot::HallEncoder& hall : halls_) hall.apply_before(segment_end_time_ + 1);
  committed_ = segment_end_;
  derivative_valid_ = false;
  committed_time_ = segment_end_time_;
  now_ = committed_time_;
  current_ = committed_;
  current_valid_ = true;
  segment_valid_ = false;
}

MechanicalState BalbotSimulation::moved_to(Nanoseconds time) {
  if (carried()) {  // the hand's motion, a cubic of time: its pieces between segment ends are that cubic again
    return carry_.at(static_cast<double>(time - carry_start_) / static_cast<double>(carry_end_ - carry_start_));
  }
  if (!derivative_valid_) {
    committed_derivative_ = mechanics_.derivative(committed_, prepared_drive());
    derivative_valid_ = true;
  }
  return mechanics_.step(committed_, committed_derivative_, prepared_drive(), seconds(time - committed_time_));
}

MechanicalState BalbotSimulation::state_at(Nanoseconds time) const {
  if (time <= committed_time_) return committed_;
  if (time >= segment_end_time_) return segment_end_;
  return segment_.at(static_cast<double>(time - committed_time_) /
                     static_cast<double>(segment_end_time_ - committed_time_));
}

void BalbotSimulation::move_to(Nanoseconds time) {
  if (time == now_) return;
  now_ = time;
  current_valid_ = false;
}

const balbot::Drive& BalbotSimulation::prepared_drive() const {
  if (!drive_prepared_) {
    drive_ = mechanics_.prepared(drive_);
    drive_prepared_ = true;
  }
  return drive_;
}

const MechanicalState& BalbotSimulation::current() const {
  if (!current_valid_) {
    current_ = state_at(now_);
    current_valid_ = true;
  }
  return current_;
}

Nanoseconds BalbotSimulation::hall_edge(std::size_t motor) const {
  return std::max(halls_[motor].next_event_time(), now_);
}

BalbotSimulation::Next BalbotSimulation::next_event() {
  Next best;
  const auto consider = [&](Nanoseconds time, Source source) {
    if (time <= segment_end_time_ && time < best.time) best = {std::max(time, now_), source};
  };
  // The order breaks ties: a restart, then a scenario change act before the interrupts of the same instant.
  consider(restart_at_, Source::restart);
  if (next_scenario_change_ < scenario_changes_.size()) {
    consider(scenario_changes_[next_scenario_change_], Source::scenario);
  }
  consider(next_pwm_period_, Source::pwm_period);
  consider(hall_edge(0), Source::left_hall);
  consider(hall_edge(1), Source::right_hall);
  consider(ultrasonic_.next_echo_edge(), Source::echo);
  consider(mpu_.next_data_ready(), Source::data_ready);
  consider(spi_done_, Source::spi);
  consider(adc_.completion(), Source::adc);
  if (next_message_ < messages_.size()) consider(messages_[next_message_].time, Source::ipc);
  return best;
}

void BalbotSimulation::raise(std::string_view interrupt) const {
  if (raise_ != nullptr) (*raise_)(interrupt);
}

void BalbotSimulation::handle(const Next& next) {
  switch (next.source) {
    case Source::restart:
      restart_at_ = never;
      pick_up_and_put_back();
      return;
    case Source::scenario: apply_scenario(); return;
    case Source::pwm_period:
      next_pwm_period_ += pwm_period;
      raise("TIM1");
      return;
    case Source::left_hall:
    case Source::right_hall: {
      const std::size_t motor = next.source == Source::left_hall ? 0 : 1;
      const balbot::HallEncoder::Taken taken = halls_[motor].take_next();
      if (taken.plan_again) {
        halls_[motor].plan(segment_.wheel, turns_, committed_time_, segment_end_time_ - committed_time_, taken.tau);
      }
      if (taken.rising_edge) {
        captures_[motor].capture(now_, true);
        raise(motor == 0 ? "TIM2" : "TIM4");
      }
      return;
    }
    case Source::echo:
      captures_[2].capture(now_, ultrasonic_.echo_edge(now_, wall_distance()));
      raise("TIM5");
      return;
    case Source::data_ready:
      if (mpu_.data_ready(now_, imu_sample(current()))) raise("EXTI8");
      return;
    case Source::spi:
      // Transmit complete, then (for a read) receive complete; SPI5 is free again before the last of them.
      spi_done_ = never;
      if (spi_read_) {
        raise("DMA2_Stream3");
        spi_busy_ = false;
        raise("DMA2_Stream2");
      } else {
        spi_busy_ = false;
        raise("DMA2_Stream3");
      }
      return;
    case Source::adc:
      if (convert_until(now_, true)) raise("DMA2_Stream4");
      return;
    case Source::ipc:
      from_linux_ = messages_[next_message_++].bytes;
      raise("IPCC_RX1");
      return;
    case Source::none: return;
  }
}

// ---- Drive -----------------------------------------------------------------------------------------------------

void BalbotSimulation::apply_scenario() {
  while (next_scenario_change_ < scenario_changes_.size() && scenario_changes_[next_scenario_change_] <= now_) {
    ++next_scenario_change_;
  }
  const auto sum = [this](const std::vector<Pulse>& pulses) {
    double total = 0;
    for (const Pulse& pulse : pulses) total += pulse.start <= now_ && now_ < pulse.end ? pulse.value : 0.0;
    return total;
  };
  push_force_ = sum(pushes_);
  disturbance_ = sum(disturbances_);
  update_drive(true, true);
}

void BalbotSimulation::update_drive(bool left, bool right) {
  const bool standby_high = pins_[static_cast<std::size_t>(Pin::standby)];
  const auto inputs = [&](Pin in1, Pin in2, Motor motor) {
    return balbot::DriverInputs{standby_high, pins_[static_cast<std::size_t>(in1)],
                                pins_[static_cast<std::size_t>(in2)],
                                duty_percent_[static_cast<std::size_t>(motor)] / 100};
  };
  if (left) left_output_ = balbot::tb6612fng(inputs(Pin::left_in1, Pin::left_in2, Motor::left), disturbance_, true);
  if (right) {
    right_output_ = balbot::tb6612fng(inputs(Pin::right_in1, Pin::right_in2, Motor::right), disturbance_, false);
  }
  const balbot::Drive next{left_output_.drive, right_output_.drive, push_force_, now_ < release_time_};
  if (same(next, drive_)) return;
  end_segment_here();
  drive_ = next;
  drive_prepared_ = false;  // worked out when next needed: several inputs often change at one instant
}

void BalbotSimulation::end_segment_here() {
  if (segment_valid_) convert_until(now_, false);
  for (balbot::HallEncoder& hall : halls_) hall.apply_before(now_);
  if (now_ > committed_time_) {
    // Something changes inside the segment: move exactly to this instant as before, start again here.
    committed_ = moved_to(now_);
    committed_time_ = now_;
    current_ = committed_;
    current_valid_ = true;
  }
  derivative_valid_ = false;
  segment_valid_ = false;
}

// ---- Disturbances ----------------------------------------------------------------------------------------------

void BalbotSimulation::plan_scenario(Nanoseconds origin) {
  pushes_.clear();
  disturbances_.clear();
  scenario_changes_.clear();
  next_scenario_change_ = 0;
  release_time_ = 0;
  if (rig_ == BalbotRig::on_ground) {
    release_time_ = origin + nanoseconds(scenario_.release_time_s);
    if (release_time_ > 0) scenario_changes_.push_back(release_time_);
  }
  for (const BalbotPush& push : scenario_.pushes) {
    add_pulse(pushes_, origin, push.time_s, push.duration_s, push.force_n);
  }
  for (const BalbotDutyDisturbance& pulse : scenario_.duty_disturbances) {
    add_pulse(disturbances_, origin, pulse.time_s, pulse.duration_s, pulse.duty);
  }
}

void BalbotSimulation::add_pulse(std::vector<Pulse>& pulses, Nanoseconds origin, double time_s, double duration_s,
                                 double value) {
  const Pulse pulse{origin + nanoseconds(time_s), origin + nanoseconds(time_s + duration_s), value};
  pulses.push_back(pulse);
  // Among the changes still to come (a pulse asked for during the run starts no earlier than now).
  for (const Nanoseconds change : {pulse.start, pulse.end}) {
    const auto ahead = scenario_changes_.begin() + static_cast<std::ptrdiff_t>(next_scenario_change_);
    scenario_changes_.insert(std::upper_bound(ahead, scenario_changes_.end(), change), change);
  }
}

void BalbotSimulation::push(const BalbotPush& push) {
  add_pulse(pushes_, 0, push.time_s, push.duration_s, push.force_n);
}

void BalbotSimulation::disturb_duty(const BalbotDutyDisturbance& pulse) {
  add_pulse(disturbances_, 0, pulse.time_s, pulse.duration_s, pulse.duty);
}

void BalbotSimulation::restart(double time_s) { restart_at_ = std::max(nanoseconds(time_s), now_); }

void BalbotSimulation::pick_up_and_put_back() {
  end_segment_here();  // the motion so far, with what moved it
  Nanoseconds origin = now_;
  if (rig_ == BalbotRig::on_ground) {
    // Grabbed: the wheels stop rolling, and the body turns about the axle (the wheels on the floor) from its tilt and
    // rate now to the scenario's tilt at rest, along a cubic: the gyroscope sees a smooth rate, no jump.
    MechanicalState from = committed_;
    from.v = 0;
    MechanicalState to = from;
    to.theta = initial_.theta;
    to.omega = 0;
    carry_ = balbot::Segment{from, to, seconds(carry_time), parameters_.wheel_radius_m};
    carry_start_ = now_;
    carry_end_ = now_ + carry_time;
    committed_ = from;
    origin = carry_end_;
  } else {
    committed_.v = initial_.v;  // the rigs hold the body still anyway: their wheels as at the start
  }
  current_ = committed_;
  current_valid_ = true;
  // The scenario starts again where the hand puts the robot down: held until its release, its pulses after.
  plan_scenario(origin);
  apply_scenario();
}

balbot::Derivative BalbotSimulation::carry_acceleration(Nanoseconds time) const {
  const double tau = static_cast<double>(time - carry_start_) / static_cast<double>(carry_end_ - carry_start_);
  const double per_second = 1 / seconds(carry_end_ - carry_start_);
  const MechanicalState s = carry_.at(tau);
  return {s.v, s.omega, carry_.x.curvature(tau) * per_second * per_second,
          carry_.theta.curvature(tau) * per_second * per_second};
}

void BalbotSimulation::set_duty(Motor motor, double percent) {
  const double duty = percent >= 0 ? std::min(percent, 100.0) : 0.0;  // NaN too: 0
  if (duty == duty_percent_[static_cast<std::size_t>(motor)]) return;
  duty_percent_[static_cast<std::size_t>(motor)] = duty;
  update_drive(motor == Motor::left, motor == Motor::right);
}

void BalbotSimulation::set_pin(Pin pin, bool high) {
  if (pins_[static_cast<std::size_t>(pin)] == high) return;
  pins_[static_cast<std::size_t>(pin)] = high;
  if (pin == Pin::trigger) {
    ultrasonic_.trigger(now_, high);
  } else {
    const bool left = pin == Pin::left_in1 || pin == Pin::left_in2 || pin == Pin::standby;
    const bool right = pin == Pin::right_in1 || pin == Pin::right_in2 || pin == Pin::standby;
    update_drive(left, right);
  }
}

double BalbotSimulation::duty_percent(Motor motor) const { return duty_percent_[static_cast<std::size_t>(motor)]; }
bool BalbotSimulation::pin(Pin pin) const { return pins_[static_cast<std::size_t>(pin)]; }

// ---- Sensors ---------------------------------------------------------------------------------------------------

balbot::ImuSample BalbotSimulation::imu_sample(const MechanicalState& s) const {
  // The specific force (acceleration minus gravity) at the sensor, sensor_height_ up the body from the axle, in the
  // sensor's axes: x forward along the body, y to the left, z up along the body. At rest a_x / a_z = tan(theta),
  // and the rotation about y is -dtheta/dt.
  const double g = parameters_.gravity_m_s2;
  const auto [sine, cosine] = balbot::sine_cosine(s.theta);
  double force_x = 0;
  double force_z = g;
  if (rig_ == BalbotRig::on_ground) {
    const balbot::Derivative d = carried() ? carry_acceleration(now_) : mechanics_.derivative(s, prepared_drive());
    const double h = sensor_height_;
    force_x = d.a - h * (cosine * d.alpha - sine * s.omega * s.omega);
    force_z = g - h * (sine * d.alpha + cosine * s.omega * s.omega);
  }
  balbot::ImuSample sample;
  sample.accel_g = {(force_x * cosine + force_z * sine) / g, 0.0, (force_z * cosine - force_x * sine) / g};
  sample.gyro_deg_s = {0.0, -s.omega * degrees_per_radian, 0.0};
  sample.temperature_c = parameters_.mpu_temperature_c;
  return sample;
}

double BalbotSimulation::wall_distance() const {
  return wall_distance_ - (rig_ == BalbotRig::on_ground ? current().x : 0.0);
}

void BalbotSimulation::spi_transaction(std::span<const double> mosi) {
  if (mosi.empty()) return;
  if (spi_busy_) {
    ++refused_spi_;  // HAL_BUSY: the previous transaction's DMA has not completed
    return;
  }
  if (mpu_.needs_sample_for(now_, mosi)) mpu_.store(imu_sample(current()));
  miso_count_ = std::min(mosi.size(), miso_.size());
  mpu_.transfer(now_, mosi, {miso_.data(), miso_count_});
  spi_busy_ = true;
  spi_read_ = (byte_of(mosi[0]) & 0x80U) != 0;
  const double bits = 8.0 * static_cast<double>(mosi.size());
  spi_done_ = now_ + std::llround(bits / parameters_.spi_clock_hz * 1e9);
}

void BalbotSimulation::spi_received(std::span<double> out) const {
  for (std::size_t i = 0; i < out.size() && i < miso_count_; ++i) out[i] = miso_[i];
}

void BalbotSimulation::capture(Capture which, std::span<double> out) const {
  const balbot::CaptureTimer& timer = captures_[static_cast<std::size_t>(which)];
  if (!out.empty()) out[0] = timer.count();
  if (out.size() > 1) out[1] = timer.rising() ? 1.0 : 0.0;
}

bool BalbotSimulation::hall_b_high(Motor motor) const {
  return halls_[static_cast<std::size_t>(motor)].b_high(mechanics_.wheel_angle(current()));
}

void BalbotSimulation::start_adc(double conversions) { adc_.start(now_, conversions); }

bool BalbotSimulation::convert_until(Nanoseconds time, bool inclusive) {
  // The conversions are not events of their own: each samples the battery at its instant on the segment's curve.
  bool completed = false;
  for (Nanoseconds at = adc_.next_conversion(); at < time || (inclusive && at == time); at = adc_.next_conversion()) {
    completed = adc_.convert(mechanics_.electrical(state_at(at), drive_).battery_v);
  }
  return completed;
}

void BalbotSimulation::adc_results(std::span<double> out) const {
  const std::span<const std::uint16_t> results = adc_.results();
  for (std::size_t i = 0; i < out.size() && i < results.size(); ++i) out[i] = results[i];
}

void BalbotSimulation::send_to_linux(std::span<const double> bytes) {
  to_linux_.clear();
  for (std::size_t i = 0; i < bytes.size() && i < most_message_bytes; ++i) to_linux_.push_back(byte_of(bytes[i]));
}

void BalbotSimulation::message_from_linux(std::span<double> out) const {
  for (std::size_t i = 0; i < out.size() && i < from_linux_.size(); ++i) out[i] = from_linux_[i];
}

void BalbotSimulation::note_unknown(std::string_view resource) {
  if (std::find(unknown_.begin(), unknown_.end(), resource) == unknown_.end()) unknown_.emplace_back(resource);
}

// ---- Truth -----------------------------------------------------------------------------------------------------

BalbotTruth BalbotSimulation::truth() const {
  const MechanicalState& s = current();
  const balbot::Electrical e = mechanics_.electrical(s, drive_);
  BalbotTruth t;
  t.time_s = seconds(now_);
  t.theta_deg = s.theta * degrees_per_radian;
  t.theta_dot_deg_s = s.omega * degrees_per_radian;
  t.x_m = s.x;
  t.v_m_s = s.v;
  t.wheel_rev_s = mechanics_.wheel_rate(s) / (2 * std::numbers::pi);
  const auto motor = [](const balbot::DriverOutputs& out, double volts, double amps, double rad_s) {
    return MotorTruth{out.mode, out.out1, out.out2, out.drive.drive, volts, amps, rad_s / (2 * std::numbers::pi)};
  };
  t.left = motor(left_output_, e.left_v, e.left_a, e.left_rad_s);
  t.right = motor(right_output_, e.right_v, e.right_a, e.right_rad_s);
  t.battery_v = e.battery_v;
  t.battery_a = e.battery_a;
  t.driver_standby = !pins_[static_cast<std::size_t>(Pin::standby)];
  t.trigger_high = ultrasonic_.trigger_high();
  t.echo_high = ultrasonic_.echo_high();
  t.wall_distance_m = wall_distance();
  t.mpu_int_high = mpu_.int_pin_high(now_);
  t.push_force_n = push_force_;
  t.duty_disturbance = disturbance_;
  return t;
}

}  // namespace duet::plant
