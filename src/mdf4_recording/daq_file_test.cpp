// A DAQ recording of two lists on two events, read back: a group per event, the A2L's names, types, units and
// conversions, raw values whose physical value is the master's, and an incomplete sample's values missing.
#include "duet/mdf4_recording/daq_file.hpp"

#include <gtest/gtest.h>

#include "duet/mdf4/reader.hpp"
#include "duet/xcp/host/values.hpp"
#include "testing/read_back.hpp"

namespace duet::mdf4_recording {
namespace {

using xcp::host::DataType;
using xcp::host::Variable;

const Variable speed{.name = "engine_speed",
                     .description = "crankshaft speed",
                     .type = DataType::uint16,
                     .unit = "rpm",
                     .conversion = {0.25, 0}};
const Variable temperatures{.name = "temperatures",
                            .description = "per cylinder",
                            .type = DataType::int16,
                            .count = 2,
                            .unit = "degC",
                            .conversion = {0.5, -40}};
const Variable gear{.name = "gear", .type = DataType::uint8, .labels = {{0, "neutral"}, {1, "first"}}};

TEST(DaqFile, AGroupPerEventWithTheA2lsChannelsAndTheMastersPhysicalValues) {
  const testing::TemporaryPath file{"daq.mf4"};
  const xcp::host::EventInfo fast{.name = "1 ms", .channel = 0, .time_cycle = 1, .time_unit = 6};
  const xcp::host::EventInfo crank{.name = "crank", .channel = 3, .time_cycle = 0};
  auto created = DaqFile::create(file.path(), {{fast, {speed, temperatures}}, {crank, {gear}}},
                                 "engine.a2l, slave tcp://ecu:5555", 1'000'000'000);
  ASSERT_TRUE(created.ok()) << created.error();
  DaqFile& daq = created.value();
  const std::vector<std::vector<std::uint8_t>> fast_samples{{0x10, 0x27, 0x50, 0x00, 0xF0, 0xFF},
                                                            {0xFF, 0xFF, 0x00, 0x80, 0xFF, 0x7F}};
  ASSERT_TRUE(daq.append(0, 0.0, fast_samples[0]).ok());
  ASSERT_TRUE(daq.append(1, 0.0005, std::vector<std::uint8_t>{1}).ok());
  ASSERT_TRUE(daq.append(0, 0.001, std::nullopt).ok());  // incomplete
  ASSERT_TRUE(daq.append(0, 0.002, fast_samples[1]).ok());
  const Status short_sample = daq.append(1, 0.003, std::vector<std::uint8_t>{});
  EXPECT_NE(short_sample.error().find("group 1 ('crank') has 1 values per sample, not 0"), std::string::npos)
      << short_sample.error();
  ASSERT_TRUE(daq.finalise().ok());

  auto reader = mdf4::Reader::open(file.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  const mdf4::FileInfo& info = reader.value().info();
  ASSERT_EQ(info.groups.size(), 2U);
  EXPECT_EQ(info.groups[0].name, "1 ms");
  EXPECT_EQ(info.groups[0].comment, "XCP event 0, every 0.001 s");
  EXPECT_EQ(info.groups[1].name, "crank");
  EXPECT_EQ(info.groups[1].comment, "XCP event 3, not periodic");
  const auto& channels = info.groups[0].channels;
  ASSERT_EQ(channels.size(), 4U);  // time, engine_speed, temperatures[0], temperatures[1]
  EXPECT_EQ(channels[1].name, "engine_speed");
  EXPECT_EQ(channels[1].unit, "rpm");
  EXPECT_EQ(channels[1].comment, "crankshaft speed");
  EXPECT_EQ(channels[1].data_type, 0);  // unsigned
  EXPECT_EQ(channels[1].bit_count, 16U);
  EXPECT_EQ(channels[1].conversion.kind, mdf4::Conversion::Kind::linear);
  EXPECT_EQ(channels[2].name, "temperatures[0]");
  EXPECT_EQ(channels[2].data_type, 2);  // signed
  EXPECT_EQ(channels[3].conversion.offset, -40);
  EXPECT_EQ(info.groups[1].channels[1].comment, "raw values, named by the A2L: 0 neutral, 1 first");
  EXPECT_EQ(info.groups[1].channels[1].conversion.kind, mdf4::Conversion::Kind::identity);

  const std::vector<testing::Sample> samples = testing::samples_of(reader.value(), 0);
  ASSERT_EQ(samples.size(), 3U);
  EXPECT_EQ(samples[1].time_s, 0.001);
  EXPECT_EQ(samples[1].valid, (std::vector<bool>{false, false, false}));
  for (std::size_t k : {0U, 2U}) {
    const std::vector<std::uint8_t>& bytes = fast_samples[k / 2];
    std::vector<double> master = xcp::host::decode(speed, std::span{bytes}.first(2));
    for (double value : xcp::host::decode(temperatures, std::span{bytes}.subspan(2))) master.push_back(value);
    EXPECT_EQ(samples[k].physical, master);
    EXPECT_EQ(samples[k].valid, (std::vector<bool>{true, true, true}));
  }
  EXPECT_EQ(samples[0].stored[0], mdf4::Number{std::uint64_t{10000}});
  EXPECT_EQ(samples[2].stored[1], mdf4::Number{std::int64_t{-32768}});
  const std::vector<testing::Sample> crank_samples = testing::samples_of(reader.value(), 1);
  ASSERT_EQ(crank_samples.size(), 1U);
  EXPECT_EQ(crank_samples[0].physical, std::vector<double>{1});
}

}  // namespace
}  // namespace duet::mdf4_recording
