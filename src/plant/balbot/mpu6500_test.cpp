#include "mpu6500.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "balbot_test_bench.hpp"

namespace duet::plant {
namespace {

using testing::BalbotBench;
using testing::initialise_mpu;
using testing::word;

constexpr double degrees_per_radian = 180 / std::numbers::pi;

struct Reading {
  double accel_tilt_deg = 0;  // atan(a_x / a_z), eq. 5.2
  double gyro_y_deg_s = 0;    // -g_y / 16.4, eq. 5.3a
  double accel_x = 0, accel_y = 0, accel_z = 0, temperature = 0, gyro_x = 0, gyro_y = 0, gyro_z = 0;
  BalbotTruth at_data_ready;  // the truth when the sample was taken
};

// The thesis' chain: EXTI8 -> a 15-byte read from 0x3B (0xBB with the read bit, then 14 dummy bytes) over SPI and
// DMA -> DMA2_Stream2 delivers the bytes.
std::vector<Reading> run_burst_reads(BalbotBench& bench, double until_s) {
  std::vector<Reading> readings;
  BalbotTruth at_data_ready;
  bench.on_interrupt = [&](std::string_view interrupt) {
    if (interrupt == "EXTI8") {
      at_data_ready = bench.plant.truth();
      EXPECT_EQ(bench.get("gpio:PE8"), 1);
      EXPECT_EQ(bench.get("exti:EXTI8"), 1);
      std::vector<double> request(15, 0.0);
      request[0] = 0x3B | 0x80;
      bench.spi(request);
    }
    if (interrupt == "DMA2_Stream2") {
      const std::vector<double> bytes = bench.get("spi:SPI5", 15);
      EXPECT_EQ(bytes[0], 0);  // clocked out while the address went in
      Reading r;
      r.accel_x = word(bytes, 1);
      r.accel_y = word(bytes, 3);
      r.accel_z = word(bytes, 5);
      r.temperature = word(bytes, 7);
      r.gyro_x = word(bytes, 9);
      r.gyro_y = word(bytes, 11);
      r.gyro_z = word(bytes, 13);
      r.accel_tilt_deg = std::atan(r.accel_x / r.accel_z) * degrees_per_radian;
      r.gyro_y_deg_s = -r.gyro_y / 16.4;
      r.at_data_ready = at_data_ready;
      readings.push_back(r);
    }
  };
  bench.run_until(until_s);
  bench.on_interrupt = {};
  return readings;
}

// One register read over SPI (the answer is there once DMA2_Stream2 has come, the next tick).
double read_register(BalbotBench& bench, int address, double at_s) {
  bench.run_until(at_s);
  bench.spi({static_cast<double>(address | 0x80), 0});
  bench.run_until(at_s + 0.001);
  return bench.get("spi:SPI5", 2)[1];
}

void write_register(BalbotBench& bench, int address, int value, double at_s) {
  bench.run_until(at_s);
  bench.spi({static_cast<double>(address), static_cast<double>(value)});
}

TEST(BalbotMpu6500, WhoAmIReadsOverSpiWithBothDmaInterrupts) {
  BalbotBench bench;
  bench.run_until(0.005);
  bench.spi({0x75 | 0x80, 0});
  bench.run_until(0.006);
  EXPECT_EQ(bench.get("spi:SPI5", 3), (std::vector<double>{0, 0x70, 0}));
  // 2 bytes at 1 MHz: both DMA interrupts 16 us after the transaction, transmit first.
  ASSERT_EQ(bench.times_of("DMA2_Stream3").size(), 1U);
  ASSERT_EQ(bench.times_of("DMA2_Stream2").size(), 1U);
  EXPECT_NEAR(bench.times_of("DMA2_Stream3")[0], 0.005016, 1e-12);
  EXPECT_NEAR(bench.times_of("DMA2_Stream2")[0], 0.005016, 1e-12);
  std::vector<std::string> order;
  for (const testing::Raised& r : bench.raised) {
    if (r.interrupt != "TIM1") order.push_back(r.interrupt);
  }
  EXPECT_EQ(order, (std::vector<std::string>{"DMA2_Stream3", "DMA2_Stream2"}));
  // A write gets only the transmit interrupt.
  bench.spi({0x1B, 0x18});
  bench.run_until(0.007);
  EXPECT_EQ(bench.times_of("DMA2_Stream3").size(), 2U);
  EXPECT_EQ(bench.times_of("DMA2_Stream2").size(), 1U);
  EXPECT_EQ(read_register(bench, 0x1B, 0.008), 0x18);
}

TEST(BalbotMpu6500, TheThesisInitialisationGivesDataReadyEveryMillisecond) {
  BalbotBench bench;
  initialise_mpu(bench, 0.010);
  bench.run_until(0.5);
  bench.run_until(1.5);
  const std::vector<double> times = bench.times_of("EXTI8");
  ASSERT_GE(times.size(), 1300U);
  EXPECT_NEAR(times.front(), 0.200, 0.0011);  // from the INT_ENABLE write on
  for (std::size_t i = 1; i < times.size(); ++i) EXPECT_NEAR(times[i] - times[i - 1], 0.001, 1e-12);
}

TEST(BalbotMpu6500, NothingIsRaisedBeforeTheInterruptIsEnabled) {
  BalbotBench bench;
  bench.run_until(0.5);
  EXPECT_TRUE(bench.times_of("EXTI8").empty());
}

TEST(BalbotMpu6500, ABurstReadDecodesToTheTrueTiltAtTheConfiguredScale) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.rig = BalbotRig::held_in_air;  // held still at 5 degrees
  BalbotBench bench{scenario};
  initialise_mpu(bench, 0.010, 0x08);  // +-4 g: 8192 LSB/g
  const std::vector<Reading> readings = run_burst_reads(bench, 0.4);
  ASSERT_GE(readings.size(), 150U);
  for (const Reading& r : readings) {
    EXPECT_NEAR(r.accel_tilt_deg, 5.0, 0.01);
    EXPECT_EQ(r.accel_x, std::round(std::sin(5 / degrees_per_radian) * 8192));
    EXPECT_EQ(r.accel_z, std::round(std::cos(5 / degrees_per_radian) * 8192));
    EXPECT_EQ(r.accel_y, 0);
    EXPECT_EQ(r.gyro_x, 0);
    EXPECT_EQ(r.gyro_y, 0);
    EXPECT_EQ(r.gyro_z, 0);
    EXPECT_NEAR(r.temperature / 333.87 + 21, 25, 0.01);
  }
}

TEST(BalbotMpu6500, TheGyroGivesTheTiltRateWhileTheRobotFalls) {
  BalbotBench bench;  // on the ground, the driver in standby: it falls from 5 degrees
  initialise_mpu(bench, 0.0, 0x08);
  const std::vector<Reading> readings = run_burst_reads(bench, 0.5);
  ASSERT_GE(readings.size(), 250U);
  EXPECT_GT(readings.back().at_data_ready.theta_dot_deg_s, 50);
  for (const Reading& r : readings) {
    EXPECT_NEAR(r.gyro_y_deg_s, r.at_data_ready.theta_dot_deg_s, 0.5 / 16.4 + 1e-9);
  }
}

TEST(BalbotMpu6500, WheelAccelerationDisturbsTheAccelerometerTilt) {
  BalbotScenario scenario = BalbotBench::quiet();
  scenario.initial_tilt_deg = 0;
  BalbotBench bench{scenario};
  initialise_mpu(bench, 0.0, 0x08);
  bench.run_until(0.250);
  bench.drive_forward(100);  // accelerating forward: the specific force leans forward, as a backward tilt would
  const std::vector<Reading> readings = run_burst_reads(bench, 0.260);
  ASSERT_GE(readings.size(), 5U);
  const Reading& r = readings[2];
  EXPECT_LT(std::abs(r.at_data_ready.theta_deg), 0.5);
  EXPECT_GT(r.accel_tilt_deg, r.at_data_ready.theta_deg + 20);  // about 2 g forward at stall torque
}

TEST(BalbotMpu6500, WritesInThe100msAfterAResetAreIgnored) {
  BalbotBench bench;
  write_register(bench, 0x1B, 0x18, 0.010);
  EXPECT_EQ(read_register(bench, 0x1B, 0.011), 0x18);
  write_register(bench, 0x6B, 0x80, 0.020);         // device reset: registers back to their defaults
  write_register(bench, 0x1B, 0x10, 0.060);         // 40 ms later: ignored
  EXPECT_EQ(read_register(bench, 0x75, 0.070), 0);  // and nothing answers
  EXPECT_EQ(read_register(bench, 0x1B, 0.125), 0);  // after 100 ms: the reset value, not 0x10
  EXPECT_EQ(read_register(bench, 0x75, 0.127), 0x70);
  EXPECT_EQ(read_register(bench, 0x6B, 0.129), 0x01);
  write_register(bench, 0x1B, 0x10, 0.131);
  EXPECT_EQ(read_register(bench, 0x1B, 0.132), 0x10);
}

TEST(BalbotMpu6500, TheIntPulseEndsAfter50usUnlessLatchedUntilIntStatusIsRead) {
  BalbotBench bench;
  initialise_mpu(bench, 0.0);
  // The pin seen from TIM1's interrupt (every 500 us): high only within 50 us of a data-ready edge.
  double last_edge = -1;
  int seen_high = 0;
  int seen_low = 0;
  bench.on_interrupt = [&](std::string_view interrupt) {
    const double now = bench.plant.truth().time_s;
    if (interrupt == "EXTI8") last_edge = now;
    if (interrupt == "TIM1" && last_edge >= 0) {
      const bool high = bench.get("gpio:PE8") == 1;
      EXPECT_EQ(high, now - last_edge < 50e-6) << now;
      (high ? seen_high : seen_low) += 1;
    }
  };
  bench.run_until(0.300);
  EXPECT_GT(seen_low, 100);
  bench.on_interrupt = {};
  const std::size_t before = bench.times_of("EXTI8").size();
  write_register(bench, 0x37, 0x20, 0.300);  // LATCH_INT_EN: INT stays high until INT_STATUS is read
  bench.run_until(0.310);
  EXPECT_EQ(bench.times_of("EXTI8").size(), before + 1);  // one more edge, then no more
  EXPECT_EQ(bench.get("gpio:PE8"), 1);
  EXPECT_EQ(read_register(bench, 0x3A, 0.310), 0x01);  // reading INT_STATUS clears it and the pin
  bench.run_until(0.320);
  EXPECT_EQ(bench.times_of("EXTI8").size(), before + 2);
  EXPECT_EQ(read_register(bench, 0x3A, 0.320), 0x01);
  bench.run_until(0.330);
  EXPECT_EQ(bench.times_of("EXTI8").size(), before + 3);
}

TEST(BalbotMpu6500, TheRangesScaleAndSaturate) {
  const BalbotParameters p;
  balbot::Mpu6500 mpu{p, nullptr};
  std::array<std::uint8_t, 2> miso{};
  const auto write = [&](int address, int value) {
    const std::array<double, 2> mosi{static_cast<double>(address), static_cast<double>(value)};
    mpu.transfer(0, mosi, miso);
  };
  const auto value = [&](int high) {
    const auto bits = static_cast<std::uint16_t>((mpu.reg(high) << 8U) | mpu.reg(high + 1));
    return static_cast<std::int16_t>(bits);
  };
  balbot::ImuSample sample;
  sample.accel_g = {3.0, -3.0, 1.0};
  sample.gyro_deg_s = {300, -300, 100};
  write(0x1C, 0x00);  // +-2 g
  write(0x1B, 0x00);  // +-250 deg/s
  mpu.store(sample);
  EXPECT_EQ(value(0x3B), 32767);
  EXPECT_EQ(value(0x3D), -32768);
  EXPECT_EQ(value(0x3F), 16384);
  EXPECT_EQ(value(0x43), 32767);
  EXPECT_EQ(value(0x45), -32768);
  EXPECT_EQ(value(0x47), 13100);
  write(0x1C, 0x18);  // +-16 g
  write(0x1B, 0x18);  // +-2000 deg/s
  mpu.store(sample);
  EXPECT_EQ(value(0x3B), 6144);
  EXPECT_EQ(value(0x3D), -6144);
  EXPECT_EQ(value(0x43), 4920);
  EXPECT_EQ(value(0x47), 1640);
}

TEST(BalbotMpu6500, NoiseHasTheThesisVariances) {
  BalbotScenario scenario;  // noise on
  scenario.rig = BalbotRig::held_in_air;
  scenario.initial_tilt_deg = 0;
  scenario.seed = 42;
  BalbotBench bench{scenario};
  initialise_mpu(bench, 0.0, 0x00);
  const std::vector<Reading> readings = run_burst_reads(bench, 4.2);
  ASSERT_GE(readings.size(), 4000U);
  const auto variance = [&](auto of) {
    double sum = 0;
    double squares = 0;
    for (const Reading& r : readings) {
      sum += of(r);
      squares += of(r) * of(r);
    }
    const auto n = static_cast<double>(readings.size());
    return squares / n - (sum / n) * (sum / n);
  };
  EXPECT_NEAR(variance([](const Reading& r) { return r.accel_tilt_deg; }), 0.8, 0.08);
  EXPECT_NEAR(variance([](const Reading& r) { return r.gyro_y_deg_s; }), 330e-6, 50e-6);
}

}  // namespace
}  // namespace duet::plant
