// The master against duet's slave in every layout the slave offers: each identification field type with each
// timestamp size, Intel and Motorola byte order, with and without fill bytes after each packet (XCP on TCP). Each
// session connects, reads the identification both ways (through the MTA and in the response), uploads, downloads,
// checksums, and records DAQ across a wrap of the slave's clock: values and times must come out right.

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <string>
#include <thread>
#include <tuple>

#include "duet/xcp/checksum.hpp"
#include "duet/xcp/host/master.hpp"
#include "test_target.hpp"

namespace duet::xcp::host {
namespace {

using Variant = std::tuple<IdentificationField, TimestampSize, ByteOrder, bool>;

class MasterAgainstSlaveVariant : public ::testing::TestWithParam<Variant> {};

std::string name_of(const ::testing::TestParamInfo<Variant>& info) {
  const auto [field, stamp, order, padded] = info.param;
  constexpr std::array fields{"absolute", "relative_byte", "relative_word", "relative_word_aligned"};
  return std::string{fields[static_cast<std::size_t>(field)]} + "_timestamp" + std::to_string(static_cast<int>(stamp)) +
         (order == ByteOrder::intel ? "_intel" : "_motorola") + (padded ? "_padded" : "");
}

TEST_P(MasterAgainstSlaveVariant, CommandsAndDaqComeOutRight) {
  const auto [field, stamp, order, padded] = GetParam();
  TestTarget target{0};
  target.configuration.identification_field = field;
  target.configuration.timestamp_size = stamp;
  target.configuration.byte_order = order;
  target.configuration.timestamp_ticks = 10;  // a tick of 10 us
  // 7 ticks a step, so that even a 1-byte timestamp unwraps; the 32-bit clock wraps at step 50, like the others.
  target.ticks_per_step = 7;
  target.clock_start = 0U - 50U * 7U;
  ASSERT_TRUE(target.server.start({.protocol = Protocol::tcp, .pad_packets = padded}).ok());
  auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", target.server.port()}, std::chrono::seconds{1});
  ASSERT_TRUE(channel.ok()) << channel.error();
  Master master{std::move(channel).value()};

  const auto properties = master.connect();
  ASSERT_TRUE(properties.ok()) << properties.error();
  EXPECT_EQ(properties.value().byte_order, order);
  EXPECT_EQ(properties.value().max_dto, 64);
  ASSERT_TRUE(master.daq_processor());
  EXPECT_EQ(master.daq_processor()->identification, field);
  EXPECT_EQ(master.daq_processor()->timestamp_size, static_cast<std::uint8_t>(stamp));
  EXPECT_DOUBLE_EQ(master.seconds_per_tick(), 10e-6);

  for (const bool in_response : {false, true}) {
    target.configuration.identification_in_response = in_response;
    const auto name = master.identification(1);
    ASSERT_TRUE(name.ok()) << name.error();
    EXPECT_EQ(std::string(name.value().begin(), name.value().end()), "duet_target") << "in response " << in_response;
  }

  const std::array<std::uint8_t, 7> values{9, 8, 7, 6, 5, 4, 3};
  ASSERT_TRUE(master.download(0, 0x2001, values).ok());
  const auto read_back = master.upload(0, 0x2001, 7);  // 7 bytes: fill follows them when padded
  ASSERT_TRUE(read_back.ok()) << read_back.error();
  EXPECT_EQ(read_back.value(), std::vector<std::uint8_t>(values.begin(), values.end()));
  const auto sum = master.checksum(0, 0x2000, 8);
  ASSERT_TRUE(sum.ok()) << sum.error();
  EXPECT_EQ(sum.value(), checksum(ChecksumType::crc_16_ccitt, target.parameters));
  const auto too_big = master.checksum(0, 0x2000, 0x0020'0000);
  EXPECT_EQ(too_big.ok() ? std::string{} : too_big.error(),
            "BUILD_CHECKSUM: ERR_OUT_OF_RANGE (0x22): the slave sums at most 1048576 bytes at once, from an address "
            "and of a size that are multiples of 1");

  const std::vector<DaqListSetup> lists{
      {.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 4}, {0, 0x1004, 2}}},
      {.event = 1, .prescaler = 2, .entries = {{0, 0x1006, 1}}},
  };
  const Status started = master.start_daq(lists);
  ASSERT_TRUE(started.ok()) << started.error();
  constexpr std::uint32_t steps = 100;
  std::thread model{[&target] {
    for (std::uint32_t number = 1; number <= steps; ++number) {
      target.step(number);
      std::this_thread::sleep_for(std::chrono::microseconds{200});
    }
  }};
  std::vector<DaqSample> fast;
  std::vector<DaqSample> slow;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds{10};
  while ((fast.size() < steps || slow.size() < steps / 4) && std::chrono::steady_clock::now() < deadline) {
    auto samples = master.receive_samples(std::chrono::milliseconds{50});
    ASSERT_TRUE(samples.ok()) << samples.error();
    for (DaqSample& sample : samples.value()) (sample.list == 0 ? fast : slow).push_back(std::move(sample));
  }
  model.join();
  ASSERT_EQ(fast.size(), steps);
  ASSERT_EQ(slow.size(), steps / 4);  // event 1 every second step, every second time
  for (std::uint32_t number = 1; number <= steps; ++number) {
    const DaqSample& sample = fast[number - 1];
    ASSERT_EQ(sample.bytes.size(), 6U);
    EXPECT_EQ(sample.bytes[0] | (sample.bytes[1] << 8U) | (sample.bytes[2] << 16U) | (sample.bytes[3] << 24U), number);
    EXPECT_EQ(sample.bytes[4] | (sample.bytes[5] << 8U), 2 * number);
    // Across the clock's wraps (every 37 steps for one byte, at step 50 for all): 7 ticks a step.
    EXPECT_EQ(sample.ticks - fast.front().ticks, 7 * static_cast<std::int64_t>(number - 1)) << "step " << number;
  }
  for (std::size_t sample = 0; sample < slow.size(); ++sample) {
    EXPECT_EQ(slow[sample].bytes, std::vector<std::uint8_t>{static_cast<std::uint8_t>(2 * (sample + 1))});
    EXPECT_EQ(slow[sample].ticks - fast.front().ticks, 7 * static_cast<std::int64_t>(4 * sample + 3));
  }
  const PacketCounters counters = master.counters();
  EXPECT_EQ(counters.lost(), 0U);
  EXPECT_EQ(counters.padded > 0, padded);
  ASSERT_TRUE(master.stop_daq().ok());
  ASSERT_TRUE(master.disconnect().ok());
  target.server.stop();
}

INSTANTIATE_TEST_SUITE_P(
    Layouts, MasterAgainstSlaveVariant,
    ::testing::Combine(::testing::Values(IdentificationField::absolute, IdentificationField::relative_byte,
                                         IdentificationField::relative_word,
                                         IdentificationField::relative_word_aligned),
                       ::testing::Values(TimestampSize::byte, TimestampSize::word, TimestampSize::dword),
                       ::testing::Values(ByteOrder::intel, ByteOrder::motorola), ::testing::Bool()),
    name_of);

}  // namespace
}  // namespace duet::xcp::host
