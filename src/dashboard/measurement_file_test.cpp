// A measurement as MDF4 bytes: each signal in its described type when every value is exactly one, else f64; NaN
// a missing sample; the header's start time from the newest time.
#include "measurement_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/summary.hpp"

namespace duet::dashboard {
namespace {

constexpr double missing = std::numeric_limits<double>::quiet_NaN();

// The stored type of one signal of `type` holding `values`, and the values read back (NaN where invalid).
std::pair<std::string, std::vector<double>> stored(const std::string& type, const std::vector<double>& values) {
  Measurement measurement{.group_name = "test",
                          .group_comment = {},
                          .file_comment = {},
                          .start_time_ns = 0,
                          .time_s = std::vector<double>(values.size(), 0.0),
                          .signals = {{.name = "x", .unit = {}, .described_type = type, .values = values}}};
  auto bytes = mdf4_bytes(measurement);
  EXPECT_TRUE(bytes.ok()) << (bytes.ok() ? "" : bytes.error());
  auto reader = mdf4::Reader::from_bytes({bytes.value().begin(), bytes.value().end()});
  EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error());
  const mdf4::GroupInfo& group = reader.value().info().groups.at(0);
  std::vector<double> read;
  EXPECT_TRUE(reader.value()
                  .for_each_record(0,
                                   [&](const mdf4::Record& record) {
                                     read.push_back(record.valid(1) ? mdf4::to_double(record.value(1)) : missing);
                                   })
                  .ok());
  return {mdf4::type_text(group.channels.at(1)), read};
}

TEST(MeasurementFile, ASignalKeepsItsTypeWhenEveryValueIsExactlyOne) {
  EXPECT_EQ(stored("int8", {-128, 127, missing}).first, "i8");
  EXPECT_EQ(stored("int8", {128}).first, "f64");
  EXPECT_EQ(stored("uint8", {-1}).first, "f64");
  EXPECT_EQ(stored("uint16", {65535, 2.5}).first, "f64");
  EXPECT_EQ(stored("int64", {-9223372036854775808.0}).first, "i64");
  EXPECT_EQ(stored("int64", {9223372036854775808.0}).first, "f64");  // 2^63: one past int64's largest
  EXPECT_EQ(stored("uint64", {18446744073709549568.0}).first, "u64");
  EXPECT_EQ(stored("uint64", {18446744073709551616.0}).first, "f64");  // 2^64
  EXPECT_EQ(stored("float32", {0.25, -0x1p100, INFINITY}).first, "f32");
  EXPECT_EQ(stored("float32", {0.1}).first, "f64");
  EXPECT_EQ(stored("float32", {1e300}).first, "f64");
  EXPECT_EQ(stored("float64", {0.1}).first, "f64");
  EXPECT_EQ(stored("", {1}).first, "f64");
  EXPECT_EQ(stored("bool", {1}).first, "f64");  // no such name in the descriptions
}

TEST(MeasurementFile, ValuesComeBackAsTheyWereAndNaNIsAMissingSample) {
  const auto [type, values] = stored("int16", {-32768, missing, 32767});
  EXPECT_EQ(type, "i16");
  ASSERT_EQ(values.size(), 3U);
  EXPECT_EQ(values[0], -32768);
  EXPECT_TRUE(std::isnan(values[1]));
  EXPECT_EQ(values[2], 32767);
  EXPECT_EQ(stored("float64", {0.1, missing}).second[0], 0.1);
  EXPECT_TRUE(std::isnan(stored("float64", {0.1, missing}).second[1]));
}

TEST(MeasurementFile, ATimeGoingBackOrValuesOfTheWrongCountFail) {
  Measurement measurement{.group_name = "test",
                          .group_comment = {},
                          .file_comment = {},
                          .start_time_ns = 0,
                          .time_s = {1, 0},
                          .signals = {{.name = "x", .unit = {}, .described_type = {}, .values = {1, 2}}}};
  const auto back = mdf4_bytes(measurement);
  ASSERT_FALSE(back.ok());
  EXPECT_NE(back.error().find("goes back in time"), std::string::npos);
  measurement.time_s = {0};
  const auto count = mdf4_bytes(measurement);
  ASSERT_FALSE(count.ok());
  EXPECT_EQ(count.error(), "signal 'x' has 2 values for 1 times");
}

TEST(MeasurementFile, TheStartTimeIsTheClockLessTheNewestTime) {
  const std::int64_t now = 1'700'000'000'000'000'000;
  EXPECT_EQ(start_time_ns(2.5, now), now - 2'500'000'000);
  EXPECT_EQ(start_time_ns(-1, now), now);
  EXPECT_EQ(start_time_ns(1e30, now), now);
}

}  // namespace
}  // namespace duet::dashboard
