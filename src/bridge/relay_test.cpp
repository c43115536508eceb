// The bridge end to end on the PC: firmware on a pty <-> the relay <-> TCP <-> duet's master.

#include "relay.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <filesystem>
#include <thread>

#include "duet/xcp/host/master.hpp"
#include "pty_firmware.hpp"

namespace duet::bridge {
namespace {

using namespace duet::xcp::host;

// Options for a relay to the tty at `path`, on any free port. (Built member by member: GCC 12 at -O3 misreads a
// braced temporary holding strings as uninitialized.)
RelayOptions options_for(const std::string& path) {
  RelayOptions options;
  options.channel.kind = ChannelKind::tty;
  options.channel.path = path;
  options.channel_uri = "tty:" + path;
  options.listen_port = 0;
  return options;
}

// A relay serving on its own thread for as long as it exists.
class RunningRelay {
 public:
  explicit RunningRelay(RelayOptions options) : relay(std::move(options)) {
    started = relay.start().ok();
    if (started) thread = std::thread{[this] { relay.run(); }};
  }
  ~RunningRelay() {
    relay.stop();
    if (thread.joinable()) thread.join();
  }
  RunningRelay(const RunningRelay&) = delete;
  RunningRelay& operator=(const RunningRelay&) = delete;

  Relay relay;
  bool started = false;
  std::thread thread;
};

class BridgeEndToEnd : public ::testing::Test {
 protected:
  void SetUp() override {
    firmware.start();
    relay = std::make_unique<Relay>(options_for(firmware.path()));
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

// A TCP connection to the relay without duet's master, for bytes no master would send; -1 if it failed.
int connect_raw(std::uint16_t port) {
  const int socket = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(socket, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    ::close(socket);
    return -1;
  }
  return socket;
}

std::size_t open_descriptors() {
  return static_cast<std::size_t>(
      std::distance(std::filesystem::directory_iterator{"/proc/self/fd"}, std::filesystem::directory_iterator{}));
}

TEST_F(BridgeEndToEnd, AMasterThatVanishesIsDisconnectedAndManyMayFollow) {
  const std::size_t descriptors_before = open_descriptors();
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
  EXPECT_LE(open_descriptors(), descriptors_before + 2);  // the last master's two ends, nothing leaked
}

TEST_F(BridgeEndToEnd, SplitFramesAndAMasterKilledMidFrame) {
  {  // half a CONNECT frame, then gone
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay->port()}, std::chrono::milliseconds{1000});
    ASSERT_TRUE(channel.ok());
  }
  const int socket = connect_raw(relay->port());
  ASSERT_GE(socket, 0);
  const std::array<std::uint8_t, 6> connect{0x02, 0x00, 0x00, 0x00, 0xFF, 0x00};
  ASSERT_EQ(::send(socket, connect.data(), 3, 0), 3);
  ::close(socket);  // killed mid-frame
  std::this_thread::sleep_for(std::chrono::milliseconds{50});
  // A master whose frames arrive a byte at a time.
  const int slow = connect_raw(relay->port());
  ASSERT_GE(slow, 0);
  for (std::uint8_t byte : connect) {
    ASSERT_EQ(::send(slow, &byte, 1, 0), 1);
    std::this_thread::sleep_for(std::chrono::milliseconds{2});
  }
  std::array<std::uint8_t, 64> answer{};
  pollfd readable{slow, POLLIN, 0};
  ASSERT_EQ(::poll(&readable, 1, 1000), 1);
  const ssize_t received = ::recv(slow, answer.data(), answer.size(), 0);
  ::close(slow);
  ASSERT_GE(received, 5);
  EXPECT_EQ(answer[4], 0xFF);  // CONNECT's positive response, framed
}

TEST(BridgeRobustness, AMasterThatStopsReadingLosesDaqFramesButNotAnswers) {
  PtyFirmware firmware;
  firmware.start();
  RelayOptions options = options_for(firmware.path());
  options.master_queue_limit = 16 * 1024;
  options.master_send_buffer = 16 * 1024;
  RunningRelay running{options};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  {
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay.port()}, std::chrono::milliseconds{1000});
    ASSERT_TRUE(channel.ok());
    Master master{std::move(channel).value()};
    ASSERT_TRUE(master.connect().ok());
    // 40 entries of 4 bytes per step: 1 kHz of 169-byte frames while the master reads nothing for 3 s.
    std::vector<DaqEntry> entries(40, DaqEntry{0, 0x1000, 4});
    ASSERT_TRUE(master.start_daq({{.event = 0, .prescaler = 1, .entries = entries}}).ok());
    std::this_thread::sleep_for(std::chrono::seconds{3});
    // Whatever was dropped, commands still get their answers.
    const auto status = master.command(std::vector<std::uint8_t>{0xFD}, "GET_STATUS");
    EXPECT_TRUE(status.ok()) << status.error() << "; " << relay.status() << "; responses " << relay.counters().responses
                             << ", gaps " << master.channel().counter_gaps() << ", received "
                             << master.channel().bytes_received();
    EXPECT_TRUE(master.stop_daq().ok());
  }
  EXPECT_GT(relay.counters().daq_frames_dropped, 0U);
}

TEST(BridgeRobustness, AChannelThatClosesIsReopenedAndServesAgain) {
  const std::filesystem::path link =
      std::filesystem::temp_directory_path() / ("duet_bridge_channel_" + std::to_string(::getpid()));
  auto first = std::make_unique<PtyFirmware>();
  first->start();
  std::filesystem::remove(link);
  std::filesystem::create_symlink(first->path(), link);  // a stable name, as /dev/ttyRPMSG0 is across restarts
  RunningRelay running{options_for(link.string())};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  auto talk = [&relay] {
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay.port()}, std::chrono::milliseconds{1000});
    if (!channel.ok()) return false;
    Master master{std::move(channel).value(), std::chrono::milliseconds{300}};
    return master.connect().ok() && master.upload(0, 0x1000, 4).ok();
  };
  EXPECT_TRUE(talk());
  first.reset();  // the firmware goes away: the channel closes
  const auto closed_by = std::chrono::steady_clock::now() + std::chrono::seconds{2};
  while (relay.channel_open() && std::chrono::steady_clock::now() < closed_by)
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  EXPECT_FALSE(relay.channel_open());
  PtyFirmware second;  // restarted
  second.start();
  std::filesystem::remove(link);
  std::filesystem::create_symlink(second.path(), link);
  const auto reopened_by = std::chrono::steady_clock::now() + std::chrono::seconds{5};
  while (!relay.channel_open() && std::chrono::steady_clock::now() < reopened_by)
    std::this_thread::sleep_for(std::chrono::milliseconds{5});
  EXPECT_TRUE(relay.channel_open());
  EXPECT_TRUE(talk());
  EXPECT_EQ(relay.counters().channel_opens, 2U);
  std::filesystem::remove(link);
}

TEST_F(BridgeEndToEnd, AMasterOnUdpIsServedAndHoldsOthersOff) {
  auto channel = MasterChannel::open({Protocol::udp, "127.0.0.1", relay->port()}, std::chrono::milliseconds{1000});
  ASSERT_TRUE(channel.ok()) << channel.error();
  Master master{std::move(channel).value(), std::chrono::milliseconds{1000}};
  ASSERT_TRUE(master.connect().ok());
  const std::array<std::uint8_t, 4> values{1, 2, 3, 4};
  ASSERT_TRUE(master.download(0, 0x2000, values).ok());
  EXPECT_EQ(master.upload(0, 0x2000, 4).value(), std::vector<std::uint8_t>(values.begin(), values.end()));

  ASSERT_TRUE(master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 4}}}}).ok());
  std::size_t samples = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds{1};
  while (std::chrono::steady_clock::now() < end)
    samples += master.receive_samples(std::chrono::milliseconds{50}).value().size();
  EXPECT_GT(samples, 900U);
  EXPECT_EQ(master.channel().counter_gaps(), 0U);

  {  // others, on TCP or UDP, are refused while it is the master
    Master on_tcp = connect(std::chrono::milliseconds{200});
    EXPECT_FALSE(on_tcp.connect().ok());
    auto other = MasterChannel::open({Protocol::udp, "127.0.0.1", relay->port()}, std::chrono::milliseconds{200});
    ASSERT_TRUE(other.ok());
    Master on_udp{std::move(other).value(), std::chrono::milliseconds{200}};
    EXPECT_FALSE(on_udp.connect().ok());
  }
  EXPECT_GE(relay->counters().masters_refused, 2U);

  ASSERT_TRUE(master.stop_daq().ok());
  ASSERT_TRUE(master.disconnect().ok());  // answered, then the master is forgotten: the next may come
  Master next = connect();
  EXPECT_TRUE(next.connect().ok());
  EXPECT_TRUE(next.upload(0, 0x1000, 4).ok());
}

TEST_F(BridgeEndToEnd, GarbageFromTheMasterIsSkippedAndCommandsWorkAfterIt) {
  const int socket = connect_raw(relay->port());
  ASSERT_GE(socket, 0);
  // Zero lengths (garbage) before a CONNECT frame, all in one write.
  const std::array<std::uint8_t, 10> bytes{0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0xFF, 0x00};
  ASSERT_EQ(::send(socket, bytes.data(), bytes.size(), 0), static_cast<ssize_t>(bytes.size()));
  std::array<std::uint8_t, 64> answer{};
  pollfd readable{socket, POLLIN, 0};
  ASSERT_EQ(::poll(&readable, 1, 1000), 1);
  const ssize_t received = ::recv(socket, answer.data(), answer.size(), 0);
  ASSERT_GE(received, 5);
  EXPECT_EQ(answer[4], 0xFF);  // CONNECT's positive response
  EXPECT_GE(relay->counters().garbage_bytes, 4U);
  EXPECT_EQ(relay->counters().frames_to_slave, 1U);  // nothing but the CONNECT reached the slave
  ::close(socket);  // (after the counters: the relay then disconnects the slave on the master's behalf)
}

}  // namespace
}  // namespace duet::bridge
