// `duet mdf info` and `duet mdf export`'s logic: the summary, and CSV with groups merged in time.
#include <gtest/gtest.h>

#include <sstream>

#include "duet/mdf4/csv_export.hpp"
#include "duet/mdf4/summary.hpp"
#include "duet/mdf4/writer.hpp"
#include "duet/version.hpp"
#include "test_files.hpp"

namespace duet::mdf4 {
namespace {

using testing::TemporaryFile;

class Mdf4Export : public ::testing::Test {
 protected:
  void SetUp() override {
    FileSpec spec{.groups = {{.name = "fast", .comment = "every 1 ms", .channels = {}},
                             {.name = "slow", .comment = "", .channels = {}}},
                  .start_time_ns = 1'800'000'000'123'456'789};
    spec.groups[0].channels = {
        {.name = "n", .type = ValueType::u8, .unit = "", .comment = ""},
        {.name = "speed", .type = ValueType::i16, .unit = "rad/s", .comment = "wheel", .conversion = Linear{0.5, 1}}};
    spec.groups[1].channels = {{.name = "n", .type = ValueType::f32, .unit = "", .comment = ""},
                               {.name = "name, quoted", .type = ValueType::boolean, .unit = "", .comment = ""}};
    auto writer = Writer::create(file.path(), spec);
    ASSERT_TRUE(writer);
    for (int tick = 0; tick < 4; ++tick) {
      const double time = tick * 0.001;
      ASSERT_TRUE(writer.value().append(
          0, time, std::vector<Value>{static_cast<std::uint8_t>(tick), tick == 1 ? Value{} : std::int16_t{-3}}));
      if (tick % 2 == 1) {
        ASSERT_TRUE(writer.value().append(1, time, std::vector<Value>{tick == 1 ? 0.1f : 0.3f, tick == 3}));
      }
    }
  }
  [[nodiscard]] Reader reader() const { return std::move(Reader::open(file.path()).value()); }
  const TemporaryFile file{"export.mf4"};
};

TEST_F(Mdf4Export, SummaryNamesGroupsChannelsUnitsSamplesAndTimeSpan) {
  auto summary = summarise(reader());
  ASSERT_TRUE(summary) << summary.error();
  EXPECT_EQ(summary.value(),
            "MDF 4.20, program \"duet\", finalised\n"
            "history: duet " +
                std::string{"0.1.0"} +
                "\n"
                "start: 2027-01-15 08:00:00.123456789 UTC\n"
                "group 0 \"fast\": 4 samples, 0 to 0.003 s (every 1 ms)\n"
                "  time: f64 [s], master\n"
                "  n: u8\n"
                "  speed: i16 [rad/s], physical = 0.5 * stored + 1 (wheel)\n"
                "group 1 \"slow\": 2 samples, 0.001 to 0.003 s\n"
                "  time: f64 [s], master\n"
                "  n: f32\n"
                "  name, quoted: u8\n");
}

TEST_F(Mdf4Export, EveryChannelMergedInTime) {
  std::ostringstream csv;
  auto exported = export_csv(reader(), {}, csv);
  ASSERT_TRUE(exported) << exported.error();
  EXPECT_EQ(exported.value().rows, 4u);
  EXPECT_EQ(exported.value().columns, 4u);
  EXPECT_EQ(csv.str(),
            "time_s,0:n,speed,1:n,\"name, quoted\"\n"
            "0,0,-0.5,,\n"
            "0.001,1,,0.1,0\n"  // speed missing at 1 ms
            "0.002,2,-0.5,,\n"
            "0.003,3,-0.5,0.3,1\n");
}

TEST_F(Mdf4Export, ChosenChannelsInTheirOrder) {
  std::ostringstream csv;
  auto exported = export_csv(reader(), {"1:n", "speed"}, csv);
  ASSERT_TRUE(exported) << exported.error();
  EXPECT_EQ(csv.str(), "time_s,1:n,speed\n0,,-0.5\n0.001,0.1,\n0.002,,-0.5\n0.003,0.3,-0.5\n");
}

TEST_F(Mdf4Export, UnknownAndAmbiguousNames) {
  std::ostringstream csv;
  EXPECT_EQ(export_csv(reader(), {"nope"}, csv).error(), "no channel 'nope' in the file (duet mdf info lists them)");
  EXPECT_EQ(export_csv(reader(), {"n"}, csv).error(), "channel 'n' is in groups 0, 1; name it as GROUP:n");
  EXPECT_EQ(export_csv(reader(), {"7:n"}, csv).error(), "no channel '7:n' in the file (duet mdf info lists them)");
}

}  // namespace
}  // namespace duet::mdf4
