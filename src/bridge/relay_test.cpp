// The bridge end to end on the PC: firmware on a pty <-> the relay <-> TCP <-> duet's master.

#include "relay.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "duet/xcp/framing.hpp"
#include "duet/xcp/host/master.hpp"
#include "duet/xcp/protocol.hpp"
#include "pseudo_terminal.hpp"
#include "pty_firmware.hpp"

namespace duet::bridge {
namespace {

using namespace duet::xcp::host;

// How long a test waits for what must come: an answer, a state of the relay. Only a guard against a hang, never what
// anything is expected to take: CI runs the tests of every build at once on two cores, the armhf ones under qemu-arm,
// and a thread may wait seconds for its turn. (Below the relay's 30 s, after which a silent UDP master is forgotten.)
constexpr std::chrono::seconds patience{20};
constexpr int patience_ms = static_cast<int>(std::chrono::milliseconds{patience}.count());  // for poll()

// Waits until `reached` holds, asking every millisecond; false if it still does not after `patience`.
template <typename Condition>
bool wait_until(Condition&& reached) {
  const auto given_up = std::chrono::steady_clock::now() + patience;
  while (!reached()) {
    if (std::chrono::steady_clock::now() >= given_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds{1});
  }
  return true;
}

// Options for a relay to the tty at `path`, on any free port. (Built member by member: GCC 12 at -O3 misreads a
// braced temporary holding strings as uninitialized.)
RelayOptions options_for(const std::string& path) {
  RelayOptions options;
  options.channel.kind = ChannelKind::tty;
  options.channel.path = path;
  options.channel_uri = "tty:" + path;
  options.listen_port = 0;
  // The firmware on the pty answers when the machine lets its thread run: an answer owed is never given up in a test
  // of anything else.
  options.owed_answer_patience = patience;
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

  Master connect(std::chrono::milliseconds timeout = patience) {
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
  std::vector<std::uint32_t> counters;  // 10 s at 1 kHz, however long the machine takes to deliver them
  const auto given_up = std::chrono::steady_clock::now() + std::chrono::seconds{10} + patience;
  while (counters.size() < 10'000 && std::chrono::steady_clock::now() < given_up) {
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
  ASSERT_GE(counters.size(), 10'000U);
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
  // Nothing follows it on the line: after the quiet gap the relay gives the lie up, byte by byte.
  ASSERT_TRUE(wait_until([this] { return relay->counters().garbage_bytes == 5; })) << relay->status();
  {
    Master intruder = connect(std::chrono::milliseconds{200});
    EXPECT_FALSE(intruder.connect().ok());
  }
  EXPECT_TRUE(master.upload(0, 0x1000, 4).ok());  // (accepted and refused by now: it came before this command)
  EXPECT_EQ(relay->counters().garbage_bytes, 5U);
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

TEST(BridgeRobustness, SplitFramesAndAMasterKilledMidFrame) {
  PtyFirmware firmware;
  firmware.start();
  RelayOptions options = options_for(firmware.path());
  options.quiet_gap = patience;  // however long the machine holds this thread between two bytes, they are one frame
  RunningRelay running{options};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  {  // half a CONNECT frame, then gone
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay.port()}, patience);
    ASSERT_TRUE(channel.ok());
  }
  const int socket = connect_raw(relay.port());
  ASSERT_GE(socket, 0);
  const std::array<std::uint8_t, 6> connect{0x02, 0x00, 0x00, 0x00, 0xFF, 0x00};
  ASSERT_EQ(::send(socket, connect.data(), 3, 0), 3);
  ::close(socket);  // killed mid-frame
  // The relay serves one master at a time: the next comes once it has taken this one (the second served) and let it
  // go, which a loaded machine may take longer to do than an idle one.
  ASSERT_TRUE(wait_until([&relay] { return relay.counters().masters_served >= 2 && !relay.master_connected(); }));
  // A master whose frames arrive a byte at a time.
  const int slow = connect_raw(relay.port());
  ASSERT_GE(slow, 0);
  for (std::uint8_t byte : connect) {
    ASSERT_EQ(::send(slow, &byte, 1, 0), 1);
    std::this_thread::sleep_for(std::chrono::milliseconds{2});
  }
  std::array<std::uint8_t, 64> answer{};
  pollfd readable{slow, POLLIN, 0};
  ASSERT_EQ(::poll(&readable, 1, patience_ms), 1);
  const ssize_t received = ::recv(slow, answer.data(), answer.size(), 0);
  ::close(slow);
  ASSERT_GE(received, 5);
  EXPECT_EQ(answer[4], 0xFF);                     // CONNECT's positive response, framed
  EXPECT_EQ(relay.counters().garbage_bytes, 3U);  // the half frame of the master killed mid-frame
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
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay.port()}, patience);
    ASSERT_TRUE(channel.ok());
    Master master{std::move(channel).value(), patience};
    ASSERT_TRUE(master.connect().ok());
    // 40 entries of 4 bytes per step: 1 kHz of 169-byte frames while the master reads nothing, until the kernel's
    // buffers and the relay's queue are full and the relay drops DAQ frames (a second or so).
    std::vector<DaqEntry> entries(40, DaqEntry{0, 0x1000, 4});
    ASSERT_TRUE(master.start_daq({{.event = 0, .prescaler = 1, .entries = entries}}).ok());
    ASSERT_TRUE(wait_until([&relay] { return relay.counters().daq_frames_dropped > 0; })) << relay.status();
    // Whatever was dropped, commands still get their answers.
    const auto status = master.command(std::vector<std::uint8_t>{0xFD}, "GET_STATUS");
    EXPECT_TRUE(status.ok()) << status.error() << "; " << relay.status() << "; responses " << relay.counters().responses
                             << ", gaps " << master.channel().counter_gaps() << ", received "
                             << master.channel().bytes_received();
    EXPECT_TRUE(master.stop_daq().ok());
  }
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
    auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay.port()}, patience);
    if (!channel.ok()) return false;
    Master master{std::move(channel).value(), patience};
    return master.connect().ok() && master.upload(0, 0x1000, 4).ok();
  };
  EXPECT_TRUE(talk());
  first.reset();  // the firmware goes away: the channel closes
  EXPECT_TRUE(wait_until([&relay] { return !relay.channel_open(); }));
  PtyFirmware second;  // restarted
  second.start();
  std::filesystem::remove(link);
  std::filesystem::create_symlink(second.path(), link);
  EXPECT_TRUE(wait_until([&relay] { return relay.channel_open(); }));
  EXPECT_TRUE(talk());
  EXPECT_EQ(relay.counters().channel_opens, 2U);
  std::filesystem::remove(link);
}

// The slave's end of a channel, written by a test byte for byte: frames in the pieces and with the pauses it wants.
class ScriptedSlave {
 public:
  [[nodiscard]] const std::string& path() const { return line_.path(); }
  void write(std::span<const std::uint8_t> bytes) const {
    ASSERT_EQ(::write(line_.descriptor(), bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
  }
  static std::vector<std::uint8_t> frame(std::uint16_t counter, std::span<const std::uint8_t> packet) {
    std::vector<std::uint8_t> bytes(xcp::ethernet_framing.frame_size(packet.size()));
    bytes.resize(xcp::write_frame(xcp::ethernet_framing, bytes, counter, packet));
    return bytes;
  }

 private:
  PseudoTerminal line_;
};

// A master on `relay` whose first packet from the slave, `first`, has come; nullptr (and a failure) otherwise.
std::unique_ptr<MasterChannel> master_after(Relay& relay, const ScriptedSlave& slave,
                                            const std::vector<std::uint8_t>& first) {
  auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay.port()}, patience);
  EXPECT_TRUE(channel.ok());
  if (!channel.ok()) return nullptr;
  EXPECT_TRUE(wait_until([&relay] { return relay.master_connected(); }));
  slave.write(ScriptedSlave::frame(40, first));
  auto received = channel.value()->receive(patience);
  EXPECT_TRUE(received.ok() && received.value() && *received.value() == first);
  return std::move(channel).value();
}

// QEMU's UART sends a byte at a time, from a thread the host may deschedule for tens of milliseconds: a frame of the
// slave's can stop part-way, its header too, for longer than the relay's quiet gap (28 ms, in the run of the
// studio's browser test's back end that failed). What has come of its header carries the counter after the slave's
// last frame, so the relay waits for the rest, which reaches the master whole with the answer behind it. Given up as
// garbage, the frame was lost and its rest, read as a header, claimed 0x8F41 bytes: with DAQ flowing no quiet gap
// came to end that, and the answer behind it was swallowed ("SET_MTA: no response within 1000 ms"). Here the line
// goes quiet after the answer, so only the frame would be lost.
TEST(BridgeRobustness, ASlaveFramePausedLongerThanTheQuietGapReachesTheMasterWhole) {
  ScriptedSlave slave;
  RunningRelay running{options_for(slave.path())};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  auto master = master_after(relay, slave, {0x00, 1, 2, 3, 4});  // the slave's frame 40
  ASSERT_NE(master, nullptr);
  std::vector<std::uint8_t> daq(105, 0x3E);  // a DAQ packet of the robot's size
  daq[0] = 0x00;
  daq[42] = 0x41;  // the bytes after the failing run's pause
  daq[43] = 0x8F;
  const std::vector<std::uint8_t> answer{0xFF, 0x00, 0x00, 0x00, 0x00, 0x00};
  std::uint16_t counter = 41;
  for (const std::size_t pause_after : {46U, 1U, 3U}) {  // bytes of the frame before the pause: 4 are its header
    ASSERT_TRUE(master->send(std::vector<std::uint8_t>{0xFD}).ok());  // GET_STATUS
    const std::vector<std::uint8_t> paused = ScriptedSlave::frame(counter++, daq);
    std::vector<std::uint8_t> rest(paused.begin() + static_cast<std::ptrdiff_t>(pause_after), paused.end());
    const std::vector<std::uint8_t> behind = ScriptedSlave::frame(counter++, answer);
    rest.insert(rest.end(), behind.begin(), behind.end());
    slave.write(std::span{paused}.first(pause_after));
    std::this_thread::sleep_for(std::chrono::milliseconds{100});
    slave.write(rest);
    for (const std::vector<std::uint8_t>& expected : {daq, answer}) {
      auto received = master->receive(patience);
      ASSERT_TRUE(received.ok()) << received.error();
      ASSERT_TRUE(received.value().has_value())
          << "paused after " << pause_after << " bytes: nothing came; " << relay.status();
      EXPECT_EQ(*received.value(), expected) << "paused after " << pause_after << " bytes";
    }
  }
  EXPECT_EQ(relay.counters().garbage_bytes, 0U);
  EXPECT_EQ(master->counter_gaps(), 0U);
}

// The quiet gap still gives up a lie: a partial frame whose counter is not the slave's next is garbage.
TEST(BridgeRobustness, APartialFrameThatIsNotTheSlavesNextIsGivenUpAfterTheQuietGap) {
  ScriptedSlave slave;
  RunningRelay running{options_for(slave.path())};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  auto master = master_after(relay, slave, {0x00, 1, 2, 3, 4});
  ASSERT_NE(master, nullptr);
  ASSERT_TRUE(master->send(std::vector<std::uint8_t>{0xFD}).ok());       // GET_STATUS
  slave.write(std::vector<std::uint8_t>{0x13, 0x00, 0x00, 0x00, 0xAB});  // "19 bytes follow", counter 0: a lie
  ASSERT_TRUE(wait_until([&relay] { return relay.counters().garbage_bytes == 5; })) << relay.status();
  const std::vector<std::uint8_t> answer{0xFF, 0x00, 0x00, 0x00, 0x00, 0x00};
  slave.write(ScriptedSlave::frame(41, answer));
  auto received = master->receive(patience);
  ASSERT_TRUE(received.ok()) << received.error();
  ASSERT_TRUE(received.value().has_value()) << "nothing came; " << relay.status();
  EXPECT_EQ(*received.value(), answer);
  EXPECT_EQ(relay.counters().garbage_bytes, 5U);
}

TEST_F(BridgeEndToEnd, AMasterOnUdpIsServedAndHoldsOthersOff) {
  auto channel = MasterChannel::open({Protocol::udp, "127.0.0.1", relay->port()}, patience);
  ASSERT_TRUE(channel.ok()) << channel.error();
  Master master{std::move(channel).value(), patience};
  ASSERT_TRUE(master.connect().ok());
  const std::array<std::uint8_t, 4> values{1, 2, 3, 4};
  ASSERT_TRUE(master.download(0, 0x2000, values).ok());
  EXPECT_EQ(master.upload(0, 0x2000, 4).value(), std::vector<std::uint8_t>(values.begin(), values.end()));

  ASSERT_TRUE(master.start_daq({{.event = 0, .prescaler = 1, .entries = {{0, 0x1000, 4}}}}).ok());
  std::size_t samples = 0;  // a second's worth, however long the machine takes to deliver them
  EXPECT_TRUE(wait_until([&] {
    samples += master.receive_samples(std::chrono::milliseconds{50}).value().size();
    return samples >= 1000;
  }));
  EXPECT_EQ(master.channel().counter_gaps(), 0U);

  {  // others, on TCP or UDP, are refused while it is the master
    Master on_tcp = connect(std::chrono::milliseconds{200});
    EXPECT_FALSE(on_tcp.connect().ok());
    auto other = MasterChannel::open({Protocol::udp, "127.0.0.1", relay->port()}, std::chrono::milliseconds{200});
    ASSERT_TRUE(other.ok());
    Master on_udp{std::move(other).value(), std::chrono::milliseconds{200}};
    EXPECT_FALSE(on_udp.connect().ok());  // never answered: its datagrams are dropped, whenever the relay reads them
  }
  EXPECT_TRUE(wait_until([this] { return relay->counters().masters_refused >= 2; }));

  ASSERT_TRUE(master.stop_daq().ok());
  ASSERT_TRUE(master.disconnect().ok());  // answered, then the master is forgotten: the next may come
  Master next = connect();
  EXPECT_TRUE(next.connect().ok());
  EXPECT_TRUE(next.upload(0, 0x1000, 4).ok());
}

TEST_F(BridgeEndToEnd, AUdpMasterWhoseDisconnectNoSlaveAnswersIsForgottenAtOnce) {
  auto channel = MasterChannel::open({Protocol::udp, "127.0.0.1", relay->port()}, patience);
  ASSERT_TRUE(channel.ok()) << channel.error();
  const std::array<std::uint8_t, 1> disconnect{0xFE};  // and no session: the slave will not answer it
  ASSERT_TRUE(channel.value()->send(disconnect).ok());
  // Served, then forgotten within the patience: not after 30 s of silence.
  EXPECT_TRUE(wait_until([this] { return relay->counters().masters_served == 1 && !relay->master_connected(); }));
  Master next = connect();
  EXPECT_TRUE(next.connect().ok());
  EXPECT_EQ(relay->counters().masters_refused, 0U);  // accepted after the datagram was read: it was forgotten then
}

TEST_F(BridgeEndToEnd, GarbageFromTheMasterIsSkippedAndCommandsWorkAfterIt) {
  const int socket = connect_raw(relay->port());
  ASSERT_GE(socket, 0);
  // Zero lengths (garbage) before a CONNECT frame, all in one write.
  const std::array<std::uint8_t, 10> bytes{0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0xFF, 0x00};
  ASSERT_EQ(::send(socket, bytes.data(), bytes.size(), 0), static_cast<ssize_t>(bytes.size()));
  std::array<std::uint8_t, 64> answer{};
  pollfd readable{socket, POLLIN, 0};
  ASSERT_EQ(::poll(&readable, 1, patience_ms), 1);
  const ssize_t received = ::recv(socket, answer.data(), answer.size(), 0);
  ASSERT_GE(received, 5);
  EXPECT_EQ(answer[4], 0xFF);  // CONNECT's positive response
  EXPECT_GE(relay->counters().garbage_bytes, 4U);
  EXPECT_EQ(relay->counters().frames_to_slave, 1U);  // nothing but the CONNECT reached the slave
  ::close(socket);  // (after the counters: the relay then disconnects the slave on the master's behalf)
}

TEST_F(BridgeEndToEnd, OnUdpAPartialFrameIsGarbageAndAFrameTooLongForADatagramIsCounted) {
  const int socket = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(relay->port());
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::connect(socket, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
  const auto answer_is_positive = [socket] {
    std::array<std::uint8_t, 2048> answer{};
    pollfd readable{socket, POLLIN, 0};
    return ::poll(&readable, 1, patience_ms) == 1 && ::recv(socket, answer.data(), answer.size(), 0) >= 5 &&
           answer[4] == xcp::pid::response;
  };
  // CONNECT, then the first three bytes of a frame that the datagram does not hold.
  const std::array<std::uint8_t, 9> connect{0x02, 0x00, 0x00, 0x00, 0xFF, 0x00, 0x05, 0x00, 0x00};
  ASSERT_EQ(::send(socket, connect.data(), connect.size(), 0), static_cast<ssize_t>(connect.size()));
  ASSERT_TRUE(answer_is_positive());
  EXPECT_EQ(relay->counters().garbage_bytes, 3U);

  // An event from the slave too long for one datagram, then GET_STATUS's answer behind it.
  std::vector<std::uint8_t> event(4 + 1500);
  event[0] = static_cast<std::uint8_t>(1500U);
  event[1] = static_cast<std::uint8_t>(1500U >> 8U);
  event[4] = xcp::pid::event;
  event[5] = static_cast<std::uint8_t>(xcp::EventCode::user);
  firmware.inject(event);
  const std::array<std::uint8_t, 5> get_status{0x01, 0x00, 0x01, 0x00, 0xFD};
  ASSERT_EQ(::send(socket, get_status.data(), get_status.size(), 0), static_cast<ssize_t>(get_status.size()));
  ASSERT_TRUE(answer_is_positive());
  EXPECT_EQ(relay->counters().answers_dropped, 1U);
  ::close(socket);
}

using Packet = std::vector<std::uint8_t>;
using Microseconds = std::chrono::duration<double, std::micro>;

// The relay's own answer to a command it cannot pass on: ERR_CMD_BUSY.
const Packet busy{xcp::pid::error, static_cast<std::uint8_t>(xcp::Error::cmd_busy)};

// Long enough that an answer paired with a command from before it would show in latency_max_us.
constexpr std::chrono::milliseconds telling_pause{100};

Master master_of(const Relay& relay, std::chrono::milliseconds timeout = patience) {
  auto channel = MasterChannel::open({Protocol::tcp, "127.0.0.1", relay.port()}, timeout);
  EXPECT_TRUE(channel.ok()) << (channel.ok() ? "" : channel.error());
  return Master{std::move(channel).value(), timeout};
}

// Runs `call`, keeping in `longest` the longest a call took: no answer to a command of it can have taken longer.
template <typename Call>
auto timed(Microseconds& longest, Call&& call) {
  const auto start = std::chrono::steady_clock::now();
  auto result = call();
  longest = std::max(longest, Microseconds{std::chrono::steady_clock::now() - start});
  return result;
}

// A master on TCP without duet's Master, for what a careful master would not do: commands without waiting for the
// answer, several in one write, leaving in the middle of a block. Keeps the longest it waited for an answer.
class RawMaster {
 public:
  explicit RawMaster(std::uint16_t port) : socket_(connect_raw(port)) {}
  ~RawMaster() { ::close(socket_); }
  RawMaster(const RawMaster&) = delete;
  RawMaster& operator=(const RawMaster&) = delete;

  // Frames the packets and sends them in one write.
  bool send(const std::vector<Packet>& packets) {
    std::vector<std::uint8_t> bytes;
    for (const Packet& packet : packets) {
      const auto size = static_cast<std::uint16_t>(packet.size());
      bytes.insert(bytes.end(), {static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8U),
                                 static_cast<std::uint8_t>(counter_), static_cast<std::uint8_t>(counter_ >> 8U)});
      ++counter_;
      bytes.insert(bytes.end(), packet.begin(), packet.end());
    }
    sent_at_ = std::chrono::steady_clock::now();
    return ::send(socket_, bytes.data(), bytes.size(), MSG_NOSIGNAL) == static_cast<ssize_t>(bytes.size());
  }

  // The next answer (a positive response or an ERR); none if it did not come within the patience.
  std::optional<Packet> answer() {
    const auto deadline = std::chrono::steady_clock::now() + patience;
    for (;;) {
      while (!packets_.empty()) {
        Packet packet = std::move(packets_.front());
        packets_.pop_front();
        if (packet[0] != xcp::pid::response && packet[0] != xcp::pid::error) continue;
        longest_wait = std::max(longest_wait, Microseconds{std::chrono::steady_clock::now() - sent_at_});
        return packet;
      }
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      pollfd readable{socket_, POLLIN, 0};
      if (left.count() <= 0 || ::poll(&readable, 1, static_cast<int>(left.count())) != 1) return std::nullopt;
      std::array<std::uint8_t, 4096> bytes{};
      const ssize_t received = ::recv(socket_, bytes.data(), bytes.size(), 0);
      if (received <= 0) return std::nullopt;
      decoder_.feed(std::span{bytes}.first(static_cast<std::size_t>(received)),
                    [this](std::uint16_t, std::span<const std::uint8_t> packet) {
                      packets_.emplace_back(packet.begin(), packet.end());
                    });
    }
  }

  Microseconds longest_wait{0};

 private:
  int socket_;
  std::uint16_t counter_ = 0;
  std::chrono::steady_clock::time_point sent_at_{};
  std::vector<std::uint8_t> buffer_ = std::vector<std::uint8_t>(xcp::ethernet_framing.frame_size(0xFFFF));
  xcp::FrameDecoder decoder_{xcp::ethernet_framing, buffer_, 0xFFFF};
  std::deque<Packet> packets_;
};

TEST(BridgeSessions, AfterAWrongKeyEndedTheSessionTheNextMastersConnectIsAnswered) {
  PtyFirmware firmware{{.calibration_locked = true}};
  firmware.start();
  RunningRelay running{options_for(firmware.path())};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  {
    Master master = master_of(relay);
    ASSERT_TRUE(master.connect().ok());
    const Status unlocked = master.unlock(xcp::resource::calibration_paging, [](std::uint8_t, auto seed) {
      return Packet(seed.begin(), seed.end());  // not the key
    });
    ASSERT_FALSE(unlocked.ok());
    EXPECT_NE(unlocked.error().find("ERR_ACCESS_LOCKED"), std::string::npos) << unlocked.error();
  }  // gone, after the slave ended the session itself
  Master next = master_of(relay);
  ASSERT_TRUE(next.connect().ok());
  const Status unlocked = next.unlock(xcp::resource::calibration_paging, [](std::uint8_t, auto seed) {
    Packet key;
    for (const std::uint8_t byte : seed) key.push_back(static_cast<std::uint8_t>(~byte));
    return key;
  });
  EXPECT_TRUE(unlocked.ok()) << unlocked.error();
  EXPECT_EQ(relay.counters().frames_without_master, 0U);  // no DISCONNECT on the first's behalf, no answer to lose
  EXPECT_EQ(relay.counters().commands_unanswered, 0U);
}

TEST(BridgeSessions, AMasterGoneInTheMiddleOfABlockDownloadLeavesTheNextOneServed) {
  PtyFirmware firmware{{.max_cto = 64}};  // 62 bytes per DOWNLOAD packet: 200 bytes take four
  firmware.start();
  RunningRelay running{options_for(firmware.path())};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  Packet block(200);
  for (std::size_t byte = 0; byte < block.size(); ++byte) block[byte] = static_cast<std::uint8_t>(byte);
  const auto part = [&block](std::uint8_t command, std::size_t at) {  // the count left, then 62 bytes
    Packet packet(2 + 62);  // sized first: GCC 12 at -O3 warns falsely about inserting into a two-byte vector
    packet[0] = command;
    packet[1] = static_cast<std::uint8_t>(block.size() - at);
    std::copy_n(block.begin() + static_cast<std::ptrdiff_t>(at), 62, packet.begin() + 2);
    return packet;
  };
  Microseconds longest{0};
  {
    RawMaster leaving{relay.port()};
    ASSERT_TRUE(leaving.send({{0xFF, 0x00}}));
    ASSERT_TRUE(leaving.answer());
    ASSERT_TRUE(leaving.send({{0xF6, 0x00, 0x00, 0x00, 0x00, 0x30, 0x00, 0x00}}));  // SET_MTA to the table
    ASSERT_TRUE(leaving.answer());
    ASSERT_TRUE(leaving.send({part(0xF0, 0), part(0xEF, 62), part(0xEF, 124)}));  // the last 14 bytes never come
    longest = leaving.longest_wait;
  }
  std::this_thread::sleep_for(telling_pause);
  Master next = master_of(relay);
  ASSERT_TRUE(timed(longest, [&next] { return next.connect(); }).ok());
  const Status downloaded = timed(longest, [&next, &block] { return next.download(0, 0x3000, block); });
  ASSERT_TRUE(downloaded.ok()) << downloaded.error();
  const auto uploaded = timed(longest, [&next] { return next.upload(0, 0x3000, 200); });
  ASSERT_TRUE(uploaded.ok()) << uploaded.error();
  EXPECT_EQ(uploaded.value(), block);
  const RelayCounters counters = relay.counters();
  EXPECT_EQ(counters.frames_without_master, 1U);  // the answer to the relay's DISCONNECT
  EXPECT_EQ(counters.commands_unanswered, 0U);
  // CONNECT and SET_MTA; then CONNECT with duet's master's GET_DAQ_PROCESSOR_INFO and GET_DAQ_RESOLUTION_INFO,
  // SET_MTA and the block's last packet; SET_MTA and four UPLOADs.
  EXPECT_EQ(counters.responses, 12U);
  EXPECT_LE(counters.latency_max_us, longest.count());
}

TEST(BridgeSessions, CommandsToADisconnectedSlaveWaitForNoAnswer) {
  PtyFirmware firmware;
  firmware.start();
  RunningRelay running{options_for(firmware.path())};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  const std::vector<Packet> statuses(1000, Packet{0xFD});  // GET_STATUS, which a disconnected slave ignores
  Microseconds longest{0};
  {
    RawMaster careless{relay.port()};
    for (int session = 0; session < 2; ++session) {
      ASSERT_TRUE(careless.send({{0xFF, 0x00}}));
      const std::optional<Packet> connected = careless.answer();
      ASSERT_TRUE(connected);
      EXPECT_EQ(connected->size(), 8U);  // CONNECT's own response
      ASSERT_TRUE(careless.send({{0xFE}}));
      ASSERT_TRUE(careless.answer());
      ASSERT_TRUE(careless.send(statuses));
      std::this_thread::sleep_for(telling_pause);
    }
    longest = careless.longest_wait;
  }  // gone while disconnected: nothing to end on its behalf
  Master next = master_of(relay);
  ASSERT_TRUE(timed(longest, [&next] { return next.connect(); }).ok());
  const RelayCounters counters = relay.counters();
  // Two sessions of CONNECT, DISCONNECT and 1000 GET_STATUS; then duet's master: CONNECT and its two DAQ questions.
  EXPECT_EQ(counters.frames_to_slave, 2007U);
  EXPECT_EQ(counters.responses, 7U);
  EXPECT_EQ(counters.commands_unanswered, 0U);
  EXPECT_EQ(counters.frames_without_master, 0U);
  EXPECT_LE(counters.latency_max_us, longest.count());
}

TEST(BridgeSessions, ACommandSentBeforeTheLastWasAnsweredLeavesThatOneUnanswered) {
  PtyFirmware firmware;
  firmware.start();
  RunningRelay running{options_for(firmware.path())};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  RawMaster impatient{relay.port()};
  ASSERT_TRUE(impatient.send({{0xFF, 0x00}}));
  ASSERT_TRUE(impatient.answer());
  ASSERT_TRUE(impatient.send({{0xFD}, {0xFD}}));  // two GET_STATUS in one write
  EXPECT_TRUE(impatient.answer());
  EXPECT_TRUE(impatient.answer());  // both answers reach the master
  const RelayCounters counters = relay.counters();
  EXPECT_EQ(counters.commands_unanswered, 1U);  // the first, given up when the second came
  EXPECT_EQ(counters.responses, 2U);            // CONNECT, and the second GET_STATUS with the first answer
  EXPECT_LE(counters.latency_max_us, impatient.longest_wait.count());
}

TEST(BridgeSessions, AnAnswerThatNeverComesHoldsTheNextMasterBackOnlyBriefly) {
  PtyFirmware firmware;
  firmware.start();
  RelayOptions options = options_for(firmware.path());
  options.owed_answer_patience = SessionTracker::default_owed_answer_patience;  // the answer that never comes
  RunningRelay running{options};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  {
    RawMaster first{relay.port()};
    ASSERT_TRUE(wait_until([&relay] { return relay.master_connected(); }));  // or the response would go to nobody
    // A positive response out of the blue, as from a session older than the relay: the relay takes the slave for
    // connected, which it is not.
    firmware.inject({0x01, 0x00, 0x00, 0x00, 0xFF});
    ASSERT_TRUE(first.answer());
  }  // gone: the relay sends DISCONNECT, which the disconnected slave does not answer
  Master next = master_of(relay);
  EXPECT_TRUE(next.connect().ok());  // held back until the relay gave the answer up, then served
  EXPECT_TRUE(next.upload(0, 0x1000, 4).ok());
  EXPECT_EQ(relay.counters().commands_unanswered, 1U);  // the relay's DISCONNECT
  // DISCONNECT; CONNECT, GET_DAQ_PROCESSOR_INFO, GET_DAQ_RESOLUTION_INFO; SET_MTA, UPLOAD.
  EXPECT_EQ(relay.counters().frames_to_slave, 6U);
}

TEST(BridgeSessions, CommandsBeforeTheChannelIsOpenAreAnsweredBusy) {
  const std::filesystem::path link =
      std::filesystem::temp_directory_path() / ("duet_bridge_late_channel_" + std::to_string(::getpid()));
  std::filesystem::remove(link);
  RunningRelay running{options_for(link.string())};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  {
    // A master repeats a command answered ERR_CMD_BUSY (duet's until its timeout): each try is refused and counted.
    RawMaster early{relay.port()};
    for (std::uint64_t tries = 1; tries <= 3; ++tries) {
      ASSERT_TRUE(early.send({{0xFF, 0x00}}));  // CONNECT
      EXPECT_EQ(early.answer(), busy);
      EXPECT_EQ(relay.counters().commands_refused, tries);
    }
  }
  PtyFirmware firmware;  // the firmware comes up
  firmware.start();
  std::filesystem::create_symlink(firmware.path(), link);
  ASSERT_TRUE(wait_until([&relay] { return relay.channel_open(); }));
  Master later = master_of(relay);
  EXPECT_TRUE(later.connect().ok());
  EXPECT_EQ(relay.counters().commands_refused, 3U);
  std::filesystem::remove(link);
}

TEST(BridgeSessions, CommandsBeyondTheQueueTowardsTheSlaveAreAnsweredBusy) {
  PtyFirmware firmware;
  firmware.start();
  RelayOptions options = options_for(firmware.path());
  options.slave_queue_limit = 32;
  RunningRelay running{options};
  ASSERT_TRUE(running.started);
  Relay& relay = running.relay;
  RawMaster master{relay.port()};
  ASSERT_TRUE(master.send({{0xFF, 0x00}}));  // CONNECT
  ASSERT_TRUE(master.answer());
  ASSERT_TRUE(master.send({{0xF6, 0x00, 0x00, 0x00, 0x00, 0x30, 0x00, 0x00}}));  // SET_MTA to the table
  ASSERT_TRUE(master.answer());
  // DOWNLOAD of 30 bytes: 32 bytes and LEN/CTR, more than may wait. Refused each time the master repeats it.
  Packet large(2 + 30, 7);
  large[0] = 0xF0;
  large[1] = 30;
  for (std::uint64_t tries = 1; tries <= 3; ++tries) {
    ASSERT_TRUE(master.send({large}));
    EXPECT_EQ(master.answer(), busy);
    EXPECT_EQ(relay.counters().commands_refused, tries);
  }
  ASSERT_TRUE(master.send({{0xF0, 4, 7, 7, 7, 7}}));  // DOWNLOAD of 4 bytes: it fits, at the MTA set before
  EXPECT_EQ(master.answer(), Packet{xcp::pid::response});
  EXPECT_EQ(relay.counters().commands_refused, 3U);
  EXPECT_EQ(firmware.table[3], 7);
}

}  // namespace
}  // namespace duet::bridge
