// duet pil's file: the plant's group first, then a group per DAQ list, appended from two threads at once; a failed
// append leaves the file finalised with what came before it, and says why.
#include "duet/mdf4_recording/plant_and_daq_file.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <thread>

#include "duet/mdf4/reader.hpp"
#include "testing/read_back.hpp"

namespace duet::mdf4_recording {
namespace {

using xcp::host::DataType;
using xcp::host::Variable;

const PlantColumns plant{{"theta_deg", "x_m"}, {"deg", "m"}};
const xcp::host::EventInfo fast{.name = "rate 1", .channel = 0, .time_cycle = 1, .time_unit = 6};
const Variable theta{.name = "theta", .type = DataType::float32, .unit = "deg"};
const Variable count{.name = "count", .type = DataType::uint16, .conversion = {2, 1}};

TEST(PlantAndDaqFile, ThePlantsGroupThenAGroupPerListAppendedFromTwoThreads) {
  const testing::TemporaryPath file{"pil.mf4"};
  auto created = PlantAndDaqFile::create(file.path(), plant, {{fast, {theta, count}}}, "duet pil", 0);
  ASSERT_TRUE(created.ok()) << created.error();
  PlantAndDaqFile& pil = *created.value();
  constexpr int ticks = 5000;
  std::thread plant_thread{[&pil] {
    for (int tick = 1; tick <= ticks; ++tick) {
      const std::vector<double> row{tick * 0.5, -tick * 0.25};
      pil.append_plant(tick * 1e-3, row);
    }
  }};
  for (int tick = 1; tick <= ticks; ++tick) {
    const float value = static_cast<float>(tick) * 0.5F;
    std::vector<std::uint8_t> bytes(6);
    std::memcpy(bytes.data(), &value, 4);
    bytes[4] = static_cast<std::uint8_t>(tick & 0xFF);
    bytes[5] = static_cast<std::uint8_t>(tick >> 8);
    pil.append_daq(0, tick * 1e-3, std::span<const std::uint8_t>{bytes});
  }
  plant_thread.join();
  ASSERT_TRUE(pil.finalise().ok());
  EXPECT_TRUE(pil.finalise().ok());  // said again, done once

  auto reader = mdf4::Reader::open(file.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  const mdf4::FileInfo& info = reader.value().info();
  EXPECT_TRUE(info.finalised);
  ASSERT_EQ(info.groups.size(), 2U);
  EXPECT_EQ(info.groups[0].name, "every tick");
  ASSERT_EQ(info.groups[0].channels.size(), 3U);
  EXPECT_EQ(info.groups[0].channels[1].name, "theta_deg");
  EXPECT_EQ(info.groups[0].channels[2].unit, "m");
  EXPECT_EQ(info.groups[0].channels[2].bit_count, 64U);
  EXPECT_EQ(info.groups[1].name, "rate 1");
  EXPECT_EQ(info.groups[1].channels[1].bit_count, 32U);  // FLOAT32_IEEE, raw
  const std::vector<testing::Sample> rows = testing::samples_of(reader.value(), 0);
  const std::vector<testing::Sample> samples = testing::samples_of(reader.value(), 1);
  ASSERT_EQ(rows.size(), std::size_t{ticks});
  ASSERT_EQ(samples.size(), std::size_t{ticks});
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double tick = static_cast<double>(k + 1);
    ASSERT_EQ(rows[k].time_s, tick * 1e-3);
    ASSERT_EQ(rows[k].physical, (std::vector<double>{tick * 0.5, -tick * 0.25}));
    ASSERT_EQ(samples[k].time_s, tick * 1e-3);
    ASSERT_EQ(samples[k].physical, (std::vector<double>{tick * 0.5, tick * 2 + 1}));
  }
}

TEST(PlantAndDaqFile, AFailedAppendKeepsWhatCameBeforeAndIsSaidAtTheEnd) {
  const testing::TemporaryPath file{"failed.mf4"};
  auto created = PlantAndDaqFile::create(file.path(), plant, {{fast, {theta}}}, "duet pil", 0);
  ASSERT_TRUE(created.ok()) << created.error();
  PlantAndDaqFile& pil = *created.value();
  pil.append_plant(0.001, std::vector<double>{1, 2});
  pil.append_plant(0.002, std::vector<double>{1});  // a value short
  pil.append_plant(0.003, std::vector<double>{3, 4});
  const Status finalised = pil.finalise();
  ASSERT_FALSE(finalised.ok());
  EXPECT_NE(finalised.error().find("group 0 ('every tick') has 2 values per sample, not 1"), std::string::npos)
      << finalised.error();
  auto reader = mdf4::Reader::open(file.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  EXPECT_TRUE(reader.value().info().finalised);
  EXPECT_EQ(reader.value().info().groups[0].samples, 1U);
  EXPECT_EQ(reader.value().info().groups[1].samples, 0U);
}

}  // namespace
}  // namespace duet::mdf4_recording
