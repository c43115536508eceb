// The master and the slave over real sockets on localhost, TCP and UDP: commands, calibration, paging, seed & key,
// and DAQ on two events at once with a prescaler, while a model thread steps.

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <thread>

#include "duet/xcp/host/master.hpp"
#include "test_target.hpp"

namespace duet::xcp::host {
namespace {

class MasterSlave : public ::testing::TestWithParam<Protocol> {};

TEST_P(MasterSlave, InteroperateOverLocalhost) {
  TestTarget target;
  ASSERT_TRUE(target.server.start({.protocol = GetParam()}).ok());
  const Endpoint endpoint{GetParam(), "127.0.0.1", target.server.port()};
  auto channel = MasterChannel::open(endpoint, std::chrono::milliseconds{1000});
  ASSERT_TRUE(channel.ok()) << channel.error();
  Master master{std::move(channel).value()};

  const Result<SlaveProperties> properties = master.connect();
  ASSERT_TRUE(properties.ok()) << properties.error();
  EXPECT_EQ(properties.value().max_cto, 32);
  EXPECT_EQ(properties.value().max_dto, 64);

  const auto name = master.identification(1);
  ASSERT_TRUE(name.ok()) << name.error();
  EXPECT_EQ(std::string(name.value().begin(), name.value().end()), "duet_target");

  // Calibration: a download longer than one packet arrives whole (block mode).
  const std::array<std::uint8_t, 8> values{10, 20, 30, 40, 50, 60, 70, 80};
  ASSERT_TRUE(master.download(0, 0x2000, values).ok());
  EXPECT_EQ(target.parameters, values);
  const auto read_back = master.upload(0, 0x2000, 8);
  ASSERT_TRUE(read_back.ok()) << read_back.error();
  EXPECT_EQ(read_back.value(), std::vector<std::uint8_t>(values.begin(), values.end()));
  const auto denied = master.upload(0, 0x5000, 4);
  EXPECT_EQ(denied.ok() ? std::string{} : denied.error(), "UPLOAD: ERR_ACCESS_DENIED (0x24)");

  // Pages: the model switches to the reference page and back.
  ASSERT_TRUE(master.set_calibration_page(0x01, 0, 1).ok());
  EXPECT_EQ(target.ecu_page, target.reference.data());
  EXPECT_EQ(master.calibration_page(0x01, 0).value(), 1);
  ASSERT_TRUE(master.set_calibration_page(0x81, 0, 0).ok());
  EXPECT_EQ(target.ecu_page, target.parameters.data());

  // DAQ is locked until seed & key.
  EXPECT_FALSE(master.start_daq({}).ok());
  ASSERT_TRUE(master.unlock(resource::daq, compute_key).ok());

  const std::vector<DaqListSetup> lists{
      {.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 4}, {0, 0x1004, 2}}},
      {.event = 1, .prescaler = 2, .entries = {{0, 0x1006, 1}}},
  };
  const Status started = master.start_daq(lists);
  ASSERT_TRUE(started.ok()) << started.error();
  std::thread model{[&target] {
    for (std::uint32_t number = 1; number <= 200; ++number) {
      target.step(number);
      std::this_thread::sleep_for(std::chrono::microseconds{200});
    }
  }};
  std::vector<DaqSample> fast;
  std::vector<DaqSample> slow;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds{10};
  while ((fast.size() < 200 || slow.size() < 50) && std::chrono::steady_clock::now() < deadline) {
    auto samples = master.receive_samples(std::chrono::milliseconds{50});
    ASSERT_TRUE(samples.ok()) << samples.error();
    for (DaqSample& sample : samples.value()) (sample.list == 0 ? fast : slow).push_back(std::move(sample));
  }
  model.join();
  ASSERT_EQ(fast.size(), 200U);
  ASSERT_EQ(slow.size(), 50U);  // event 1 came 100 times; prescaler 2
  for (std::uint32_t number = 1; number <= 200; ++number) {
    const std::vector<std::uint8_t>& bytes = fast[number - 1].bytes;
    ASSERT_EQ(bytes.size(), 6U);
    EXPECT_EQ(bytes[0] | (bytes[1] << 8U) | (bytes[2] << 16U) | (bytes[3] << 24U), number);
    EXPECT_EQ(bytes[4] | (bytes[5] << 8U), 2 * number);
  }
  for (std::size_t sample = 0; sample < slow.size(); ++sample) {
    // Event 1 comes at steps 2, 4, 6, ... with slow = 1, 2, 3, ...; the prescaler keeps every second occurrence.
    EXPECT_EQ(slow[sample].bytes, std::vector<std::uint8_t>{static_cast<std::uint8_t>(2 * (sample + 1))});
  }
  EXPECT_EQ(master.channel().counter_gaps(), 0U);
  EXPECT_EQ(master.overload_events(), 0U);
  ASSERT_TRUE(master.stop_daq().ok());
  ASSERT_TRUE(master.disconnect().ok());
  target.server.stop();
}

INSTANTIATE_TEST_SUITE_P(Transports, MasterSlave, ::testing::Values(Protocol::tcp, Protocol::udp),
                         [](const ::testing::TestParamInfo<Protocol>& protocol) {
                           return protocol.param == Protocol::tcp ? std::string{"tcp"} : std::string{"udp"};
                         });

TEST(SlaveServer, RefusesASecondMasterAndEndsTheSessionOfOneThatLeaves) {
  TestTarget target;
  ASSERT_TRUE(target.server.start({}).ok());
  const Endpoint endpoint{Protocol::tcp, "127.0.0.1", target.server.port()};
  {
    auto first = MasterChannel::open(endpoint, std::chrono::milliseconds{1000});
    ASSERT_TRUE(first.ok());
    Master master{std::move(first).value()};
    ASSERT_TRUE(master.connect().ok());
    EXPECT_TRUE(target.slave.connected());
    {
      auto second = MasterChannel::open(endpoint, std::chrono::milliseconds{1000});
      ASSERT_TRUE(second.ok());
      Master intruder{std::move(second).value(), std::chrono::milliseconds{300}};
      EXPECT_FALSE(intruder.connect().ok());
    }
    EXPECT_EQ(target.server.refused_masters(), 1U);
    EXPECT_TRUE(master.upload(0, 0x1000, 4).ok());  // the first master is still served
  }                                                 // it goes away without DISCONNECT
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds{5};
  while (target.slave.connected() && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds{1});
  }
  EXPECT_FALSE(target.slave.connected());
}

}  // namespace
}  // namespace duet::xcp::host
