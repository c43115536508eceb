// The streams the link runs over: socket pairs, pipes and TCP; timeouts instead of hangs; HOST:PORT.
#include "duet/link/stream.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <thread>

#include "duet/link/tcp.hpp"

namespace duet::link {
namespace {

using namespace std::chrono_literals;

const std::array<std::uint8_t, 5> hello{'h', 'e', 'l', 'l', 'o'};

void exchange(Stream& a, Stream& b) {
  ASSERT_TRUE(a.write_all(hello).ok());
  std::array<std::uint8_t, 5> got{};
  const Status read = b.read_exactly(got);
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_EQ(got, hello);
}

TEST(LinkStream, ASocketPairCarriesBytesBothWays) {
  auto pair = socket_pair(1s);
  ASSERT_TRUE(pair.ok()) << pair.error();
  exchange(*pair.value().first, *pair.value().second);
  exchange(*pair.value().second, *pair.value().first);
}

TEST(LinkStream, APipePairCarriesBytesBothWays) {
  auto pair = pipe_pair(1s);
  ASSERT_TRUE(pair.ok()) << pair.error();
  exchange(*pair.value().first, *pair.value().second);
  exchange(*pair.value().second, *pair.value().first);
}

TEST(LinkStream, ASilentPeerTimesOut) {
  auto pair = socket_pair(50ms);
  ASSERT_TRUE(pair.ok());
  std::array<std::uint8_t, 4> bytes{};
  const auto start = std::chrono::steady_clock::now();
  auto got = pair.value().first->read_some(bytes);
  ASSERT_FALSE(got.ok());
  EXPECT_EQ(got.error(), "nothing received for 50 ms");
  EXPECT_GE(std::chrono::steady_clock::now() - start, 50ms);
}

TEST(LinkStream, TheEndOfTheStreamIsZeroBytesOrAFailureInTheMiddle) {
  auto pair = socket_pair(1s);
  ASSERT_TRUE(pair.ok());
  ASSERT_TRUE(pair.value().first->write_all(std::span{hello}.first(2)).ok());
  pair.value().first.reset();
  std::array<std::uint8_t, 5> bytes{};
  const Status cut = pair.value().second->read_exactly(bytes);
  ASSERT_FALSE(cut.ok());
  EXPECT_EQ(cut.error(), "the stream ended after 2 of 5 bytes");
  auto end = pair.value().second->read_some(bytes);
  ASSERT_TRUE(end.ok());
  EXPECT_EQ(end.value(), 0U);
}

TEST(LinkStream, WritingToAPeerThatIsGoneFailsWithoutSignal) {
  for (const bool pipes : {false, true}) {
    auto pair = pipes ? pipe_pair(1s) : socket_pair(1s);
    ASSERT_TRUE(pair.ok());
    pair.value().second.reset();
    const Status written = pair.value().first->write_all(hello);  // SIGPIPE would end the test program here
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error(), "the peer closed the stream");
  }
}

TEST(LinkStream, AFullPeerTimesOutInsteadOfBlocking) {
  auto pair = socket_pair(50ms);
  ASSERT_TRUE(pair.ok());
  const std::vector<std::uint8_t> lots(16 << 20, 0x55);  // more than a socket buffers
  const Status written = pair.value().first->write_all(lots);
  ASSERT_FALSE(written.ok());
  EXPECT_EQ(written.error(), "the peer took no bytes for 50 ms");
}

TEST(LinkTcp, ListenConnectAccept) {
  auto listener = TcpListener::open({"127.0.0.1", 0});
  ASSERT_TRUE(listener.ok()) << listener.error();
  const HostPort address = listener.value().address();
  EXPECT_NE(address.port, 0);
  std::unique_ptr<FdStream> client;
  std::thread connecting{[&] {
    auto connected = connect_tcp(address, 2s);
    EXPECT_TRUE(connected.ok()) << connected.error();
    if (connected) client = std::move(connected).value();
  }};
  auto accepted = listener.value().accept(2s, 1s);
  connecting.join();
  ASSERT_TRUE(accepted.ok()) << accepted.error();
  ASSERT_NE(client, nullptr);
  EXPECT_TRUE(accepted.value().peer.starts_with("127.0.0.1:")) << accepted.value().peer;
  exchange(*client, *accepted.value().stream);
  exchange(*accepted.value().stream, *client);
}

TEST(LinkTcp, NobodyListening) {
  auto listener = TcpListener::open({"127.0.0.1", 0});
  ASSERT_TRUE(listener.ok());
  const HostPort address = listener.value().address();
  listener = TcpListener::open({"127.0.0.1", 0});  // the first one closes: its port is free again
  auto refused = connect_tcp(address, 1s);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error(), "cannot connect to " + to_string(address) + ": Connection refused");
  auto accepted = listener.value().accept(20ms);
  ASSERT_FALSE(accepted.ok());
  EXPECT_EQ(accepted.error(), "no connection within 20 ms");
}

TEST(LinkTcp, HostPort) {
  EXPECT_EQ(parse_host_port("127.0.0.1:5601").value(), (HostPort{"127.0.0.1", 5601}));
  EXPECT_EQ(parse_host_port("localhost:0").value(), (HostPort{"localhost", 0}));
  EXPECT_EQ(parse_host_port(":7000").value(), (HostPort{"127.0.0.1", 7000}));
  EXPECT_EQ(parse_host_port("[::1]:5601").value(), (HostPort{"::1", 5601}));
  EXPECT_EQ(to_string(HostPort{"::1", 5601}), "[::1]:5601");
  EXPECT_EQ(parse_host_port("127.0.0.1").error(), "'127.0.0.1' is not HOST:PORT (no ':' before the port)");
  EXPECT_EQ(parse_host_port("host:65536").error(),
            "'host:65536' is not HOST:PORT (the port must be a number from 0 to 65535)");
  EXPECT_FALSE(parse_host_port("host:").ok());
  EXPECT_FALSE(parse_host_port("host:12x").ok());
  EXPECT_FALSE(parse_host_port("::1:5601").ok());
  EXPECT_FALSE(parse_host_port("[::1:5601").ok());
}

}  // namespace
}  // namespace duet::link
