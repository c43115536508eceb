// A simulation's recording as an MDF file: the program's signals in their exact types (a vector as its elements), the
// plant's columns as doubles, and a value its type does not hold refused with its place.
#include "duet/mdf4_recording/recording_file.hpp"

#include <gtest/gtest.h>

#include "duet/mdf4/reader.hpp"
#include "testing/read_back.hpp"

namespace duet::mdf4_recording {
namespace {

// Signals built member by member: GCC 12 at -O3 misreads a braced temporary holding a vector as uninitialized.
model::ProgramSignal signal(const std::string& name, model::DataType type, std::vector<std::size_t> shape,
                            const std::string& unit, const std::string& description) {
  model::ProgramSignal signal;
  signal.name = name;
  signal.type.type = type;
  signal.type.shape = std::move(shape);
  signal.unit = unit;
  signal.description = description;
  return signal;
}

model::Program program_of_three_signals() {
  model::Program program;
  program.signals.push_back(signal("mode", model::DataType::uint8, {}, "", "state"));
  program.signals.push_back(signal("on", model::DataType::boolean, {}, "", ""));
  program.signals.push_back(signal("x", model::DataType::int16, {2}, "mm", "where"));
  return program;
}

model::Recording recording_of_three_signals() {
  return {.names = {"mode", "on", "x[0]", "x[1]", "plant.theta"},
          .units = {"", "", "mm", "mm", "deg"},
          .signals = {0, 1, 2, 2, std::nullopt},
          .time_s = {0, 0.001},
          .columns = {{0, 3}, {1, 0}, {-5, 7}, {32767, -32768}, {0.1, 0.2}}};
}

TEST(RecordingFile, SignalsInTheirExactTypesAndThePlantsAsDoubles) {
  const testing::TemporaryPath file{"sim.mf4"};
  const model::Program program = program_of_three_signals();
  const Status written = write_recording_file(file.path(), recording_of_three_signals(),
                                              {.group = "base rate 1 ms", .comment = "m.yaml", .program = &program});
  ASSERT_TRUE(written.ok()) << written.error();
  auto reader = mdf4::Reader::open(file.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  ASSERT_EQ(reader.value().info().groups.size(), 1U);
  const mdf4::GroupInfo& group = reader.value().info().groups[0];
  EXPECT_EQ(group.name, "base rate 1 ms");
  ASSERT_EQ(group.channels.size(), 6U);
  const std::vector<std::string> names{"time", "mode", "on", "x[0]", "x[1]", "plant.theta"};
  const std::vector<std::uint32_t> bits{64, 8, 8, 16, 16, 64};
  const std::vector<std::uint8_t> types{4, 0, 0, 2, 2, 4};
  for (std::size_t k = 0; k < names.size(); ++k) {
    EXPECT_EQ(group.channels[k].name, names[k]);
    EXPECT_EQ(group.channels[k].bit_count, bits[k]) << names[k];
    EXPECT_EQ(group.channels[k].data_type, types[k]) << names[k];
  }
  EXPECT_EQ(group.channels[3].unit, "mm");
  EXPECT_EQ(group.channels[3].comment, "where");
  EXPECT_EQ(group.channels[5].unit, "deg");
  const std::vector<testing::Sample> samples = testing::samples_of(reader.value(), 0);
  ASSERT_EQ(samples.size(), 2U);
  EXPECT_EQ(samples[1].time_s, 0.001);
  EXPECT_EQ(samples[1].physical, (std::vector<double>{3, 0, 7, -32768, 0.2}));
  EXPECT_EQ(samples[0].stored[3], mdf4::Number{std::int64_t{32767}});
}

TEST(RecordingFile, WithoutAProgramEveryColumnIsADouble) {
  const testing::TemporaryPath file{"plant.mf4"};
  const Status written = write_recording_file(file.path(), recording_of_three_signals(), {.group = "every tick"});
  ASSERT_TRUE(written.ok()) << written.error();
  auto reader = mdf4::Reader::open(file.path());
  ASSERT_TRUE(reader.ok()) << reader.error();
  for (const mdf4::ChannelInfo& channel : reader.value().info().groups[0].channels) EXPECT_EQ(channel.bit_count, 64U);
}

TEST(RecordingFile, AValueItsSignalsTypeDoesNotHoldIsAnErrorNamingItsPlace) {
  const testing::TemporaryPath file{"bad.mf4"};
  const model::Program program = program_of_three_signals();
  model::Recording recording = recording_of_three_signals();
  recording.columns[2][1] = 0.5;
  const Status written = write_recording_file(file.path(), recording, {.group = "g", .program = &program});
  EXPECT_EQ(written.error(), file.path().string() + ": x[0] at 0.001 s: 0.5 is no i16 value");
}

}  // namespace
}  // namespace duet::mdf4_recording
