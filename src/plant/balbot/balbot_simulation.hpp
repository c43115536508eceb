#pragma once
// The robot's time line: the physics integrated in segments between the points where the drive changes (and at
// most 1 ms long), the peripherals' events in time order inside them, and the typed accesses the resources map to.
// BalbotPlant (balbot_plant.cpp) maps the model's resource names onto these calls.

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "battery_adc.hpp"
#include "capture_timer.hpp"
#include "duet/plant/balbot/balbot_parameters.hpp"
#include "duet/plant/balbot/balbot_scenario.hpp"
#include "duet/plant/balbot/balbot_truth.hpp"
#include "duet/plant/plant.hpp"
#include "fast_normal.hpp"
#include "hall_encoder.hpp"
#include "mechanics.hpp"
#include "motor_driver.hpp"
#include "mpu6500.hpp"
#include "segment.hpp"
#include "ultrasonic_sensor.hpp"

namespace duet::plant {

class BalbotSimulation {
 public:
  enum class Motor { left, right };
  enum class Pin { right_in1, right_in2, left_in1, left_in2, standby, trigger };
  enum class Capture { left_hall, right_hall, echo };
  static constexpr std::size_t most_message_bytes = 496;  // one RPMsg payload
  static constexpr std::size_t most_spi_bytes = 256;

  BalbotSimulation(const BalbotScenario& scenario, const BalbotParameters& parameters);

  void advance(balbot::Nanoseconds target, const RaiseInterrupt& raise);

  // Disturbances asked for during the run (BalbotPlant::disturb), from `time_s` on, the time of the next advance():
  // exactly what the scenario's own pushes and duty disturbances planned for then do.
  void push(const BalbotPush& push);
  void disturb_duty(const BalbotDutyDisturbance& pulse);
  // The robot picked up at `time_s` and put back as the scenario starts it (README.md, "Restart").
  void restart(double time_s);

  // The model drives.
  void set_duty(Motor motor, double percent);
  void set_pin(Pin pin, bool high);
  void spi_transaction(std::span<const double> mosi);
  void start_adc(double conversions);
  void send_to_linux(std::span<const double> bytes);

  // The model reads. Each fills what it has and leaves the rest of `out` alone.
  [[nodiscard]] double duty_percent(Motor motor) const;
  [[nodiscard]] bool pin(Pin pin) const;
  void spi_received(std::span<double> out) const;
  [[nodiscard]] bool mpu_int_high() const { return mpu_.int_pin_high(now_); }
  void capture(Capture which, std::span<double> out) const;
  [[nodiscard]] bool hall_b_high(Motor motor) const;
  void adc_results(std::span<double> out) const;
  void message_from_linux(std::span<double> out) const;

  [[nodiscard]] BalbotTruth truth() const;
  [[nodiscard]] std::span<const std::uint8_t> message_to_linux() const { return to_linux_; }
  [[nodiscard]] std::uint64_t refused_spi_transactions() const { return refused_spi_; }
  // A resource name the robot does not have: remembered once (the only allocation after construction).
  void note_unknown(std::string_view resource);
  [[nodiscard]] const std::vector<std::string>& unknown_resources() const { return unknown_; }

 private:
  using Nanoseconds = balbot::Nanoseconds;
  enum class Source { restart, scenario, pwm_period, left_hall, right_hall, echo, data_ready, spi, adc, ipc, none };
  struct Next {
    Nanoseconds time = balbot::never;
    Source source = Source::none;
  };
  struct Pulse {  // a scenario force or disturbance acting on [start, end)
    Nanoseconds start = 0;
    Nanoseconds end = 0;
    double value = 0;
  };
  struct Message {
    Nanoseconds time = 0;
    std::vector<std::uint8_t> bytes;
  };

  void ensure_segment(Nanoseconds target);
  void commit_segment();
  void end_segment_here();
  // The motion from the committed state to `time` inside the segment ahead: integrated with the drive, or the hand's.
  [[nodiscard]] balbot::MechanicalState moved_to(Nanoseconds time);
  [[nodiscard]] bool carried() const { return committed_time_ < carry_end_; }
  void pick_up_and_put_back();
  // The scenario's release and pulses from `origin` on, in place of anything planned before.
  void plan_scenario(Nanoseconds origin);
  void add_pulse(std::vector<Pulse>& pulses, Nanoseconds origin, double time_s, double duration_s, double value);
  [[nodiscard]] balbot::Derivative carry_acceleration(Nanoseconds time) const;
  void move_to(Nanoseconds time);
  [[nodiscard]] balbot::MechanicalState state_at(Nanoseconds time) const;
  [[nodiscard]] const balbot::MechanicalState& current() const;
  [[nodiscard]] const balbot::Drive& prepared_drive() const;
  [[nodiscard]] Next next_event();
  [[nodiscard]] Nanoseconds hall_edge(std::size_t motor) const;
  void plan_halls();
  bool convert_until(Nanoseconds time, bool inclusive);  // the battery ADC's conversions due by then
  void handle(const Next& next);
  void raise(std::string_view interrupt) const;
  void apply_scenario();
  void update_drive(bool left, bool right);
  [[nodiscard]] balbot::ImuSample imu_sample(const balbot::MechanicalState& s) const;
  [[nodiscard]] double wall_distance() const;

  BalbotParameters parameters_;
  BalbotRig rig_;
  double sensor_height_;
  double wall_distance_;
  balbot::Mechanics mechanics_;
  balbot::FastNormal imu_noise_;
  balbot::FastNormal adc_noise_;

  // Integration: the committed state, the segment ahead of it (to seg_end_time_) and the state now.
  balbot::MechanicalState committed_;
  balbot::Derivative committed_derivative_;
  Nanoseconds committed_time_ = 0;
  Nanoseconds segment_end_time_ = 0;
  balbot::MechanicalState segment_end_;
  balbot::Segment segment_;
  Nanoseconds now_ = 0;
  mutable balbot::MechanicalState current_;  // the state at now_, worked out when asked for
  const RaiseInterrupt* raise_ = nullptr;

  // Drive.
  std::array<double, 2> duty_percent_{};
  balbot::DriverOutputs left_output_;
  balbot::DriverOutputs right_output_;
  double push_force_ = 0;
  Nanoseconds release_time_ = 0;  // held still before
  double disturbance_ = 0;
  mutable balbot::Drive drive_;
  std::vector<Pulse> pushes_;
  std::vector<Pulse> disturbances_;
  std::vector<Nanoseconds> scenario_changes_;  // sorted
  std::size_t next_scenario_change_ = 0;

  // Restart: what the scenario plans, relative to its start, to plan again; a restart asked for; the hand's motion.
  BalbotScenario scenario_;
  balbot::MechanicalState initial_;
  Nanoseconds restart_at_ = balbot::never;
  balbot::Segment carry_;
  Nanoseconds carry_start_ = 0;
  Nanoseconds carry_end_ = 0;
  Nanoseconds next_pwm_period_;

  // Sensors.
  std::array<balbot::HallEncoder, 2> halls_;
  balbot::TurningPoints turns_;  // of the segment's wheel angle
  std::array<balbot::CaptureTimer, 3> captures_{};
  balbot::Mpu6500 mpu_;
  std::array<std::uint8_t, most_spi_bytes> miso_{};
  std::size_t miso_count_ = 0;
  Nanoseconds spi_done_ = balbot::never;
  std::uint64_t refused_spi_ = 0;
  balbot::UltrasonicSensor ultrasonic_;
  balbot::BatteryAdc adc_;

  // The application channel.
  std::vector<std::uint8_t> to_linux_;
  std::vector<std::uint8_t> from_linux_;
  std::vector<Message> messages_;
  std::size_t next_message_ = 0;
  std::vector<std::string> unknown_;

  // Flags last, together (no padding between larger members).
  bool derivative_valid_ = false;        // committed_derivative_ is derivative(committed_, drive_)
  bool segment_valid_ = false;           // the segment ahead is integrated for drive_
  mutable bool current_valid_ = true;    // current_ is the state at now_
  mutable bool drive_prepared_ = false;  // drive_'s torque line is worked out
  std::array<bool, 6> pins_{};           // by Pin
  bool spi_busy_ = false;                // a transaction's DMA has not completed
  bool spi_read_ = false;                // that transaction reads
};

}  // namespace duet::plant
