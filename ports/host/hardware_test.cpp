// The PC's typed hardware calls: each resource reaches the plant by its name, as doubles, whole however many values
// it has, and comes back converted as the interpreter converts (duet::blocks::convert).
#include "duet/hardware/hardware.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "duet/plant/plant.hpp"

namespace duet::hardware {
namespace {

// Keeps what was written; a read gives k + 0.75 for value k, so that conversions show.
class RecordingPlant : public plant::Plant {
 public:
  void advance(double, const plant::RaiseInterrupt&) override {}
  void write(std::string_view resource, std::span<const double> values) override {
    written_to = resource;
    written.assign(values.begin(), values.end());
  }
  void read(std::string_view resource, std::span<double> values) override {
    read_from = resource;
    for (std::size_t k = 0; k < values.size(); ++k) values[k] = static_cast<double>(k) + 0.75;
  }
  std::string written_to;
  std::vector<double> written;
  std::string read_from;
};

class HostHardware : public ::testing::Test {
 protected:
  HostHardware() { connect(&plant); }
  ~HostHardware() override { connect(nullptr); }
  RecordingPlant plant;
};

TEST_F(HostHardware, EveryValueOfALongSequenceReachesThePlant) {
  std::vector<std::uint8_t> bytes(300);
  for (std::size_t k = 0; k < bytes.size(); ++k) bytes[k] = static_cast<std::uint8_t>(k);
  spi_transfer<spi("SPI5")>(bytes);
  EXPECT_EQ(plant.written_to, "spi:SPI5");
  ASSERT_EQ(plant.written.size(), 300U);
  EXPECT_EQ(plant.written[299], 43.0);  // 299 as a byte

  std::vector<std::uint16_t> samples(1000);
  adc_samples<adc("ADC1", 6)>(samples);
  EXPECT_EQ(plant.read_from, "adc:ADC1/6");
  EXPECT_EQ(samples[0], 0);  // 0.75, converted as the interpreter does
  EXPECT_EQ(samples[999], blocks::convert<std::uint16_t>(999.75));
}

TEST_F(HostHardware, EachKindByThePlantsName) {
  pwm_write<pwm("TIM1", 3)>(12.5F);
  EXPECT_EQ(plant.written_to, "pwm:TIM1/3");
  EXPECT_EQ(plant.written, std::vector<double>{12.5});
  adc_start<adc("ADC1", 6)>(100);
  EXPECT_EQ(plant.written, std::vector<double>{100.0});
  const CaptureReading hall = capture_read<capture("TIM2", 1)>();
  EXPECT_EQ(plant.read_from, "capture:TIM2/1");
  EXPECT_EQ(hall.count, blocks::convert<std::uint32_t>(0.75));
  EXPECT_EQ(hall.rising, blocks::convert<bool>(1.75));
  const std::array<std::uint8_t, 2> message{7, 9};
  ipc_send<ipc("app")>(message);
  EXPECT_EQ(plant.written_to, "ipc:app");
  EXPECT_EQ(plant.written, (std::vector<double>{7.0, 9.0}));
}

}  // namespace
}  // namespace duet::hardware
