// The bridge end to end on the PC: firmware on a pty <-> the relay <-> TCP <-> duet's master.

#include "relay.hpp"

#include <gtest/gtest.h>

#include <thread>

#include "duet/xcp/host/master.hpp"
#include "pty_firmware.hpp"

namespace duet::bridge {
namespace {

using namespace duet::xcp::host;

class BridgeEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    firmware.start();
    relay = std::make_unique<Relay>(RelayOptions{
        .channel = {ChannelKind::tty, firmware.path(), 0}, .channel_uri = "tty:" + firmware.path(), .listen_port = 0});
    ASSERT_TRUE(relay->start().ok());
    thread = std::thread{[this] { relay->run(); }};
  }
  void TearDown() override {
    relay->stop();
    thread.join();
  }

  Master connect(std::chrono::milliseconds timeout = std::chrono::milliseconds{1000}) {
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay->port()}, timeout);
    EXPECT_TRUE(channel.ok()) << (channel.ok() ? "" : channel.error());
    return Master{std::move(channel).value(), timeout};
  }

  PtyFirmware firmware;
  std::unique_ptr<Relay> relay;
  std::thread thread;
};

TEST_F(BridgeEndToEnd, CommandsAndTenSecondsOfDaqAtOneKilohertzWithoutLoss) {
  Master master = connect();
  ASSERT_TRUE(master.connect().ok());
  const auto name = master.identification(1);
  ASSERT_TRUE(name.ok()) << name.error();
  EXPECT_EQ(std::string(name.value().begin(), name.value().end()), "pty_firmware");
  const std::array<std::uint8_t, 4> values{1, 2, 3, 4};
  ASSERT_TRUE(master.download(0, 0x2000, values).ok());
  EXPECT_EQ(master.upload(0, 0x2000, 4).value(), std::vector<std::uint8_t>(values.begin(), values.end()));

  ASSERT_TRUE(master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 4}}}}).ok());
  std::vector<std::uint32_t> counters;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds{10};
  while (std::chrono::steady_clock::now() < end) {
    auto samples = master.receive_samples(std::chrono::milliseconds{50});
    ASSERT_TRUE(samples.ok()) << samples.error();
    for (const DaqSample& sample : samples.value()) {
      std::uint32_t value = 0;
      for (std::size_t byte = 0; byte < 4; ++byte)
        value |= static_cast<std::uint32_t>(sample.bytes[byte]) << (8U * byte);
      counters.push_back(value);
    }
  }
  ASSERT_TRUE(master.stop_daq().ok());
  ASSERT_GT(counters.size(), 9000U);  // 10 s at 1 kHz, give or take the PC's scheduling
  std::size_t gaps = 0;
  for (std::size_t index = 1; index < counters.size(); ++index)
    gaps += counters[index] != counters[index - 1] + 1 ? 1U : 0U;
  EXPECT_EQ(gaps, 0U);
  EXPECT_EQ(master.channel().counter_gaps(), 0U);
  EXPECT_EQ(relay->counters().daq_frames_dropped, 0U);
}

TEST_F(BridgeEndToEnd, GarbageOnTheChannelIsSkippedAndASecondMasterRefused) {
  Master master = connect();
  ASSERT_TRUE(master.connect().ok());
  firmware.inject({0x13, 0x00, 0x00, 0x00, 0xAB});  // a frame header that lies, then noise
  std::this_thread::sleep_for(std::chrono::milliseconds{20});
  {
    Master intruder = connect(std::chrono::milliseconds{200});
    EXPECT_FALSE(intruder.connect().ok());
  }
  // The lying header swallowed bytes until its frame was complete; the commands after it work again.
  bool worked = false;
  for (int attempt = 0; attempt < 5 && !worked; ++attempt) worked = master.upload(0, 0x1000, 4).ok();
  EXPECT_TRUE(worked);
  EXPECT_GT(relay->counters().garbage_bytes, 0U);
  EXPECT_EQ(relay->counters().masters_refused, 1U);
}

TEST_F(BridgeEndToEnd, AMasterThatVanishesIsDisconnectedAndManyMayFollow) {
  {
    Master master = connect();
    ASSERT_TRUE(master.connect().ok());
    ASSERT_TRUE(master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 4}}}}).ok());
  }  // gone without DISCONNECT, DAQ running
  for (int cycle = 0; cycle < 1000; ++cycle) {
    Master master = connect();
    ASSERT_TRUE(master.connect().ok()) << "cycle " << cycle;
    if (cycle % 100 == 0) {
      ASSERT_TRUE(master.upload(0, 0x1000, 4).ok());
    }
  }
  Master last = connect();
  ASSERT_TRUE(last.connect().ok());
  auto samples = last.receive_samples(std::chrono::milliseconds{100});
  ASSERT_TRUE(samples.ok());
  EXPECT_TRUE(samples.value().empty());  // the first master's DAQ was stopped on its behalf
  EXPECT_EQ(relay->counters().masters_served, 1002U);
}

}  // namespace
}  // namespace duet::bridge
