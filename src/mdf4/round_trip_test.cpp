// Everything the writer writes, read back bit for bit by the reader.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>

#include "duet/mdf4/reader.hpp"
#include "duet/mdf4/writer.hpp"
#include "test_files.hpp"

namespace duet::mdf4 {
namespace {

using testing::TemporaryFile;

// Bit patterns, compared as such: a float NaN's payload and a negative zero must survive.
template <typename T>
auto bits(T value) {
  if constexpr (std::is_floating_point_v<T>) {
    return std::bit_cast<std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>(value);
  } else {
    return value;
  }
}

std::vector<std::vector<Value>> every_type_samples() {
  const auto float_nan = std::bit_cast<float>(0x7FA00001u);  // a signalling NaN with a payload
  const auto double_nan = std::bit_cast<double>(0x7FF4000000000123ull);
  return {
      {true, std::uint8_t{0}, std::uint16_t{0}, std::uint32_t{0}, std::uint64_t{0}, std::int8_t{0}, std::int16_t{0},
       std::int32_t{0}, std::int64_t{0}, 0.0f, 0.0},
      {false, std::uint8_t{255}, std::uint16_t{65535}, std::uint32_t{4294967295u},
       std::numeric_limits<std::uint64_t>::max(), std::int8_t{-128}, std::int16_t{-32768},
       std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int64_t>::min(), -0.0f, -0.0},
      {true, std::uint8_t{1}, std::uint16_t{1}, std::uint32_t{1}, std::uint64_t{1} << 63, std::int8_t{127},
       std::int16_t{32767}, std::numeric_limits<std::int32_t>::max(), std::numeric_limits<std::int64_t>::max(),
       float_nan, double_nan},
      {false, std::uint8_t{7}, std::uint16_t{300}, std::uint32_t{70000}, std::uint64_t{1234567890123}, std::int8_t{-1},
       std::int16_t{-2}, std::int32_t{-3}, std::int64_t{-4}, std::numeric_limits<float>::infinity(),
       std::numeric_limits<double>::denorm_min()},
  };
}

GroupSpec every_type_group() {
  GroupSpec group{.name = "every type", .comment = "one channel of each type", .channels = {}};
  const char* names[] = {"flag", "u8", "u16", "u32", "u64", "i8", "i16", "i32", "i64", "f32", "f64"};
  for (int type = 0; type <= static_cast<int>(ValueType::f64); ++type)
    group.channels.push_back({.name = names[type], .type = static_cast<ValueType>(type), .unit = "", .comment = ""});
  return group;
}

// The stored value read back, as the writer was given it.
bool same(const Value& written, const Number& read) {
  return std::visit(
      [&](auto value) {
        using T = decltype(value);
        if constexpr (std::is_same_v<T, std::monostate>) {
          return false;
        } else if constexpr (std::is_same_v<T, bool>) {
          return std::get<std::uint64_t>(read) == (value ? 1u : 0u);
        } else if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
          return std::holds_alternative<T>(read) && bits(std::get<T>(read)) == bits(value);
        } else if constexpr (std::is_signed_v<T>) {
          return std::get<std::int64_t>(read) == value;
        } else {
          return std::get<std::uint64_t>(read) == value;
        }
      },
      written);
}

TEST(Mdf4RoundTrip, EveryTypeBitForBit) {
  const TemporaryFile file{"types.mf4"};
  const auto samples = every_type_samples();
  {
    auto writer = Writer::create(file.path(), FileSpec{.groups = {every_type_group()}});
    ASSERT_TRUE(writer) << writer.error();
    for (std::size_t sample = 0; sample < samples.size(); ++sample)
      ASSERT_TRUE(writer.value().append(0, 0.001 * static_cast<double>(sample), samples[sample]));
    ASSERT_TRUE(writer.value().finalise());
  }
  auto reader = Reader::open(file.path());
  ASSERT_TRUE(reader) << reader.error();
  const FileInfo& info = reader.value().info();
  EXPECT_TRUE(info.finalised);
  EXPECT_EQ(info.version, "4.20");
  EXPECT_EQ(info.version_number, 420);
  EXPECT_EQ(info.program, "duet");
  ASSERT_EQ(info.groups.size(), 1u);
  const GroupInfo& group = info.groups[0];
  EXPECT_EQ(group.name, "every type");
  EXPECT_EQ(group.comment, "one channel of each type");
  EXPECT_EQ(group.samples, samples.size());
  ASSERT_EQ(group.channels.size(), 12u);
  ASSERT_EQ(group.master, 0u);
  EXPECT_EQ(group.channels[0].name, "time");
  EXPECT_EQ(group.channels[0].unit, "s");
  EXPECT_EQ(group.channels[2].name, "u8");
  std::size_t read = 0;
  ASSERT_TRUE(reader.value().for_each_record(0, [&](const Record& record) {
    EXPECT_EQ(record.time(), 0.001 * static_cast<double>(read));
    for (std::size_t channel = 0; channel < samples[read].size(); ++channel) {
      EXPECT_TRUE(record.valid(channel + 1));
      EXPECT_TRUE(same(samples[read][channel], record.value(channel + 1)))
          << "sample " << read << " channel " << channel;
    }
    ++read;
  }));
  EXPECT_EQ(read, samples.size());
}

TEST(Mdf4RoundTrip, NamesUnitsCommentsConversionsAndVectors) {
  const TemporaryFile file{"described.mf4"};
  FileSpec spec{.groups = {{.name = "rate 10", .comment = "", .channels = {}}},
                .start_time_ns = 1'700'000'000'000'000'000};
  spec.groups[0].channels = {
      {.name = "speed",
       .type = ValueType::i16,
       .unit = "rad/s",
       .comment = "wheel speed",
       .conversion = Linear{0.01, -2.5}},
      {.name = "current", .type = ValueType::f32, .unit = "A", .comment = "", .conversion = {}, .elements = 3}};
  {
    auto writer = Writer::create(file.path(), spec);
    ASSERT_TRUE(writer) << writer.error();
    const std::vector<Value> values{std::int16_t{-1000}, 1.5f, 2.5f, 3.5f};
    ASSERT_TRUE(writer.value().append(0, 0.5, values));
  }  // the destructor finalises
  auto reader = Reader::open(file.path());
  ASSERT_TRUE(reader) << reader.error();
  const FileInfo& info = reader.value().info();
  EXPECT_TRUE(info.finalised);
  EXPECT_EQ(info.start_time_ns, 1'700'000'000'000'000'000u);
  ASSERT_EQ(info.history.size(), 1u);
  EXPECT_EQ(info.history[0].rfind("duet ", 0), 0u) << info.history[0];
  const GroupInfo& group = info.groups[0];
  ASSERT_EQ(group.channels.size(), 5u);
  EXPECT_EQ(group.channels[1].name, "speed");
  EXPECT_EQ(group.channels[1].unit, "rad/s");
  EXPECT_EQ(group.channels[1].comment, "wheel speed");
  EXPECT_EQ(group.channels[1].conversion.kind, Conversion::Kind::linear);
  EXPECT_EQ(group.channels[1].conversion.factor, 0.01);
  EXPECT_EQ(group.channels[1].conversion.offset, -2.5);
  EXPECT_EQ(group.channels[2].name, "current[0]");
  EXPECT_EQ(group.channels[4].name, "current[2]");
  EXPECT_EQ(group.channels[4].unit, "A");
  ASSERT_TRUE(reader.value().for_each_record(0, [&](const Record& record) {
    EXPECT_EQ(std::get<std::int64_t>(record.value(1)), -1000);
    EXPECT_EQ(std::get<double>(record.physical(1)), 0.01 * -1000 - 2.5);
    EXPECT_EQ(std::get<float>(record.value(3)), 2.5f);
    EXPECT_EQ(std::get<float>(std::get<Number>(record.physical(4))), 3.5f);
  }));
}

TEST(Mdf4RoundTrip, MissingSamplesAreInvalidAndTheOthersValid) {
  const TemporaryFile file{"missing.mf4"};
  GroupSpec group{.name = "g", .comment = "", .channels = {}};
  for (int channel = 0; channel < 10; ++channel)
    group.channels.push_back({.name = "c" + std::to_string(channel), .type = ValueType::u8, .unit = "", .comment = ""});
  {
    auto writer = Writer::create(file.path(), FileSpec{.groups = {group}});
    ASSERT_TRUE(writer);
    for (int sample = 0; sample < 10; ++sample) {
      std::vector<Value> values;
      values.reserve(10);
      for (int channel = 0; channel < 10; ++channel)
        values.push_back(channel == sample ? Value{} : Value{static_cast<std::uint8_t>(channel)});
      ASSERT_TRUE(writer.value().append(0, sample, values));
    }
  }
  auto reader = Reader::open(file.path());
  ASSERT_TRUE(reader) << reader.error();
  EXPECT_EQ(reader.value().info().groups[0].invalidation_bytes, 2u);
  ASSERT_TRUE(reader.value().for_each_record(0, [&](const Record& record) {
    EXPECT_TRUE(record.valid(0));  // the time
    for (std::size_t channel = 0; channel < 10; ++channel) {
      EXPECT_EQ(record.valid(channel + 1), channel != record.index()) << record.index() << " " << channel;
      if (channel != record.index()) {
        EXPECT_EQ(std::get<std::uint64_t>(record.value(channel + 1)), channel);
      }
    }
  }));
}

// Three rates interleaved as they arrive, in small fragments so that each group's data is a chain of many blocks.
TEST(Mdf4RoundTrip, SeveralGroupsAtDifferentRatesInFragments) {
  const TemporaryFile file{"rates.mf4"};
  FileSpec spec;
  const int periods_ms[] = {1, 10, 100};
  for (const int period : periods_ms)
    spec.groups.push_back({.name = "every " + std::to_string(period) + " ms",
                           .comment = "",
                           .channels = {{.name = "count", .type = ValueType::u32, .unit = "", .comment = ""},
                                        {.name = "x", .type = ValueType::f64, .unit = "m", .comment = ""}}});
  constexpr int milliseconds = 5000;
  {
    auto writer = Writer::create(file.path(), spec, WriterOptions{.fragment_bytes = 256});
    ASSERT_TRUE(writer);
    for (int now = 0; now < milliseconds; ++now) {
      for (std::size_t group = 0; group < 3; ++group) {
        if (now % periods_ms[group] != 0) continue;
        const std::vector<Value> values{static_cast<std::uint32_t>(now / periods_ms[group]), std::sin(now * 0.001)};
        ASSERT_TRUE(writer.value().append(group, now * 0.001, values));
      }
    }
    ASSERT_TRUE(writer.value().finalise());
    EXPECT_FALSE(writer.value().append(0, 10, std::vector<Value>{std::uint32_t{0}, 0.0}));  // finalised
  }
  auto reader = Reader::open(file.path());
  ASSERT_TRUE(reader) << reader.error();
  for (std::size_t group = 0; group < 3; ++group) {
    EXPECT_EQ(reader.value().info().groups[group].samples,
              static_cast<std::uint64_t>(milliseconds / periods_ms[group]));
    std::uint32_t expected = 0;
    ASSERT_TRUE(reader.value().for_each_record(group, [&](const Record& record) {
      const int now = static_cast<int>(expected) * periods_ms[group];
      EXPECT_EQ(std::get<std::uint64_t>(record.value(1)), expected);
      EXPECT_EQ(std::get<double>(record.value(2)), std::sin(now * 0.001));
      EXPECT_EQ(record.time(), now * 0.001);
      ++expected;
    }));
    auto span = reader.value().time_span(group);
    ASSERT_TRUE(span && span.value());
    EXPECT_EQ(span.value()->first, 0.0);
    EXPECT_EQ(span.value()->second, (milliseconds - periods_ms[group]) * 0.001);
  }
}

TEST(Mdf4RoundTrip, AGroupWithoutSamples) {
  const TemporaryFile file{"empty.mf4"};
  {
    auto writer = Writer::create(file.path(), FileSpec{.groups = {every_type_group()}});
    ASSERT_TRUE(writer);
  }
  auto reader = Reader::open(file.path());
  ASSERT_TRUE(reader) << reader.error();
  EXPECT_EQ(reader.value().info().groups[0].samples, 0u);
  EXPECT_FALSE(reader.value().time_span(0).value());
}

TEST(Mdf4Writer, RejectsSamplesThatDoNotFit) {
  const TemporaryFile file{"wrong.mf4"};
  auto writer = Writer::create(
      file.path(),
      FileSpec{.groups = {{.name = "g",
                           .comment = "",
                           .channels = {{.name = "a", .type = ValueType::i16, .unit = "", .comment = ""}}}}});
  ASSERT_TRUE(writer);
  const Status wrong_type = writer.value().append(0, 0, std::vector<Value>{1.0});
  EXPECT_EQ(wrong_type.error(), file.path().string() + ": group 0 ('g'): channel 'a' is i16, the sample gave f64");
  EXPECT_EQ(writer.value().append(0, 0, std::vector<Value>{}).error(),
            file.path().string() + ": group 0 ('g') has 1 values per sample, not 0");
  EXPECT_EQ(writer.value().append(3, 0, std::vector<Value>{}).error(),
            file.path().string() + ": there is no group 3 (the file has 1)");
  ASSERT_TRUE(writer.value().append(0, 1, std::vector<Value>{std::int16_t{1}}));
  EXPECT_FALSE(writer.value().append(0, 0.5, std::vector<Value>{std::int16_t{1}}));  // back in time
  EXPECT_FALSE(writer.value().append(0, NAN, std::vector<Value>{std::int16_t{1}}));
  EXPECT_EQ(Writer::create("/nonexistent/x.mf4", FileSpec{}).error(),
            "/nonexistent/x.mf4: cannot create: No such file or directory");
}

}  // namespace
}  // namespace duet::mdf4
