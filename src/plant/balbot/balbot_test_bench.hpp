#pragma once
// For the tests: a BalbotPlant advanced tick by tick (1 ms) like the simulation does, with the interrupts it raises
// recorded and handed to a test's handler (which plays the model's interrupt tasks), and helpers for the model's
// side of the SPI bus.

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "duet/plant/balbot/balbot_plant.hpp"

namespace duet::plant::testing {

struct Raised {
  double time_s = 0;
  std::string interrupt;
};

class BalbotBench {
 public:
  explicit BalbotBench(const BalbotScenario& scenario = quiet(), const BalbotParameters& parameters = {})
      : plant(scenario, parameters) {}

  // The defaults without noise.
  static BalbotScenario quiet() {
    BalbotScenario scenario;
    scenario.noise = false;
    return scenario;
  }

  // Advances tick by tick up to and including `time_s`; `each_tick` runs after each advance (the periodic tasks).
  void run_until(double time_s, const std::function<void(double)>& each_tick = {}) {
    const auto last = static_cast<std::int64_t>(std::llround(time_s * 1000));
    for (; tick_ <= last; ++tick_) {
      const double now = static_cast<double>(tick_) * 1e-3;
      plant.advance(now, raise_);
      if (each_tick) each_tick(now);
    }
  }

  [[nodiscard]] std::vector<double> times_of(std::string_view interrupt) const {
    std::vector<double> times;
    for (const Raised& r : raised) {
      if (r.interrupt == interrupt) times.push_back(r.time_s);
    }
    return times;
  }

  void set(std::string_view resource, double value) {
    const double values[] = {value};
    plant.write(resource, values);
  }
  [[nodiscard]] double get(std::string_view resource) {
    double value = 0;
    plant.read(resource, {&value, 1});
    return value;
  }
  [[nodiscard]] std::vector<double> get(std::string_view resource, std::size_t count) {
    std::vector<double> values(count);
    plant.read(resource, values);
    return values;
  }
  void spi(const std::vector<double>& bytes) { plant.write("spi:SPI5", bytes); }

  // Both motors forward (left clockwise, right counter-clockwise) at `percent`, the driver operating.
  void drive_forward(double percent) {
    set("gpio:PA12", 1);
    set("gpio:PE9", 1);
    set("gpio:PD1", 0);
    set("gpio:PE10", 0);
    set("gpio:PD14", 1);
    set("pwm:TIM1/4", percent);
    set("pwm:TIM1/3", percent);
  }

  BalbotPlant plant;
  std::vector<Raised> raised;
  std::function<void(std::string_view)> on_interrupt;  // the model's interrupt tasks
  bool record = true;

 private:
  std::int64_t tick_ = 0;
  RaiseInterrupt raise_ = [this](std::string_view interrupt) {
    if (record) raised.push_back({plant.truth().time_s, std::string{interrupt}});
    if (on_interrupt) on_interrupt(interrupt);
  };
};

// The MPU6500 set up as the thesis' initialisation does it (a register write every 10 ms), writing each step inside
// the tick at `start_s + 10 ms * step`: device reset, 100 ms wait, clock, I2C off, sample rate divider, low-pass
// filter, +-2000 deg/s, the accelerometer range, data-ready interrupt on.
inline void initialise_mpu(BalbotBench& bench, double start_s, double accel_config = 0x08) {
  const std::vector<std::vector<double>> writes{{0x6B, 0x80}, {0x6B, 0x01}, {0x6A, 0x10},         {0x19, 0x00},
                                                {0x1A, 0x01}, {0x1B, 0x18}, {0x1C, accel_config}, {0x38, 0x01}};
  bench.run_until(start_s, {});
  bench.spi(writes[0]);
  bench.run_until(start_s + 0.120);  // past the reset's 100 ms
  for (std::size_t i = 1; i < writes.size(); ++i) {
    bench.run_until(start_s + 0.120 + 0.010 * static_cast<double>(i));
    bench.spi(writes[i]);
  }
}

// A 16-bit big-endian two's-complement word from two MISO bytes.
inline double word(const std::vector<double>& bytes, std::size_t high) {
  const auto bits =
      static_cast<std::uint16_t>((static_cast<unsigned>(bytes[high]) << 8U) | static_cast<unsigned>(bytes[high + 1]));
  return static_cast<std::int16_t>(bits);
}

// A controller as the model would run it: EXTI8 requests the burst read, DMA2_Stream2 filters the tilt
// (complementary filter of atan2(a_x, a_z) and -g_y / 16.4), the 1 ms periodic task runs a PID on it and sets the
// driver's pins as the thesis' motor logic does. Motors driven by voltage turn the wheels at a speed proportional to
// the duty, so a PD on the tilt alone cannot balance; the integral term (the thesis' tunable I) makes it.
class BalancingController {
 public:
  explicit BalancingController(BalbotBench& bench) : bench_(bench) {
    bench.on_interrupt = [this](std::string_view interrupt) {
      if (interrupt == "EXTI8") {
        std::vector<double> request(15, 0.0);
        request[0] = 0x3B | 0x80;
        bench_.spi(request);
      }
      if (interrupt == "DMA2_Stream2") {
        const std::vector<double> bytes = bench_.get("spi:SPI5", 15);
        const double accel_tilt = std::atan2(word(bytes, 1), word(bytes, 5)) * 180 / std::numbers::pi;
        rate_ = -word(bytes, 11) / 16.4;
        theta_ = samples_++ == 0 ? accel_tilt : 0.998 * (theta_ + rate_ * 1e-3) + 0.002 * accel_tilt;
      }
    };
  }

  // The periodic task.
  void step() {
    if (samples_ == 0) return;
    const bool stop = std::abs(theta_) > 60;
    const double integral = integral_ + theta_ * 1e-3;
    double y = -(0.1 * theta_ + 3.0 * integral + 0.005 * rate_);
    // Clamping anti-windup, as the thesis' PID has: lying on the floor, held or saturated, nothing winds up.
    if (!stop && std::abs(y) < 1)
      integral_ = integral;
    else
      y = -(0.1 * theta_ + 3.0 * integral_ + 0.005 * rate_);
    bench_.set("gpio:PA12", stop ? 0 : 1);
    bench_.set("gpio:PE9", y >= 0 ? 1 : 0);  // left: forward is clockwise
    bench_.set("gpio:PD1", y >= 0 ? 0 : 1);
    bench_.set("gpio:PE10", y >= 0 ? 0 : 1);  // right: outputs swapped (mirrored motor)
    bench_.set("gpio:PD14", y >= 0 ? 1 : 0);
    const double duty = std::min(std::abs(y), 1.0) * 100;
    bench_.set("pwm:TIM1/4", duty);
    bench_.set("pwm:TIM1/3", duty);
  }

  [[nodiscard]] double theta() const { return theta_; }

 private:
  BalbotBench& bench_;
  double theta_ = 0;
  double rate_ = 0;
  double integral_ = 0;
  int samples_ = 0;
};

// The MPU6500 set up as fast as it allows (reset, 100 ms, then a write per tick), then the controller; the truth
// after every tick. `after_tick` runs last in each tick (a test's disturbances for the next one).
inline std::vector<std::array<double, BalbotTruth::count>> balance(
    const BalbotScenario& scenario, double seconds,
    const std::function<void(double now, BalbotPlant& plant, const BalancingController& controller)>& after_tick = {}) {
  BalbotBench bench{scenario};
  bench.record = false;
  BalancingController controller{bench};
  std::vector<std::array<double, BalbotTruth::count>> truth;
  const std::vector<std::vector<double>> writes{{0x6B, 0x01}, {0x6A, 0x10}, {0x19, 0x00}, {0x1A, 0x01},
                                                {0x1B, 0x18}, {0x1C, 0x08}, {0x38, 0x01}};
  bench.spi({0x6B, 0x80});
  bench.run_until(seconds, [&](double now) {
    const auto tick = static_cast<std::size_t>(std::llround(now * 1000));
    if (tick >= 101 && tick < 101 + writes.size()) bench.spi(writes[tick - 101]);
    controller.step();
    truth.push_back(bench.plant.truth().values());
    if (after_tick) after_tick(now, bench.plant, controller);
  });
  return truth;
}

}  // namespace duet::plant::testing
