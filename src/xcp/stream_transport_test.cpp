#include "duet/xcp/stream_transport.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace duet::xcp {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct Line {
  std::array<std::uint8_t, 16> signals{1, 2, 3, 4};
  std::array<MemoryRegion, 1> regions{
      MemoryRegion{.name = "signals", .address = 0x100, .size = 16, .memory = signals.data()}};
  std::array<EventChannel, 1> events{EventChannel{.name = "step"}};
  std::array<DaqList, 1> lists{};
  std::array<Odt, 1> odts{};
  std::array<OdtEntry, 2> entries{};
  std::array<std::uint8_t, 256> queue_storage{};
  TransmitQueue queue{queue_storage, {}};
  SlaveConfiguration configuration{.memory = MemoryMap{regions},
                                   .max_cto = 8,
                                   .max_dto = 8,
                                   .events = events,
                                   .daq = {lists, odts, entries},
                                   .queue = &queue};
  Slave slave{configuration};
  std::array<std::uint8_t, 16> decoder_buffer{};
  std::array<std::uint8_t, 8> packet_buffer{};
  StreamTransport transport{slave, queue, ethernet_framing, decoder_buffer, 8, packet_buffer};

  Bytes frame(std::uint16_t counter, const Bytes& packet) const {
    Bytes bytes(ethernet_framing.frame_size(packet.size()));
    write_frame(ethernet_framing, bytes, counter, packet);
    return bytes;
  }
  Bytes sent(std::size_t room = 64) {
    Bytes out(room);
    out.resize(transport.transmit(out));
    return out;
  }
};

TEST(StreamTransport, CommandsInPiecesGetFramedResponsesInOneCounterSequence) {
  Line line;
  const Bytes connect = line.frame(0, {0xFF, 0x00});
  line.transport.receive(std::span{connect}.first(3));
  EXPECT_TRUE(line.sent().empty());  // half a frame: nothing yet
  line.transport.receive(std::span{connect}.subspan(3));
  EXPECT_EQ(line.sent(), line.frame(0, {0xFF, 0x05, 0x80, 0x08, 0x08, 0x00, 0x01, 0x01}));
  Bytes two = line.frame(1, {0xF4, 0x02, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00});
  const Bytes synch = line.frame(2, {0xFC});
  two.insert(two.end(), synch.begin(), synch.end());
  line.transport.receive(two);
  Bytes expected = line.frame(1, {0xFF, 0x01, 0x02});
  const Bytes error = line.frame(2, {0xFE, 0x00});
  expected.insert(expected.end(), error.begin(), error.end());
  EXPECT_EQ(line.sent(), expected);
}

TEST(StreamTransport, DaqPacketsFollowInTheSameSequenceAndWaitForRoom) {
  Line line;
  for (const Bytes& command : {Bytes{0xFF, 0x00}, Bytes{0xD5, 0x00, 0x01, 0x00}, Bytes{0xD4, 0x00, 0x00, 0x00, 0x01},
                               Bytes{0xD3, 0x00, 0x00, 0x00, 0x00, 0x01}, Bytes{0xE2, 0x00, 0x00, 0x00, 0x00, 0x00},
                               Bytes{0xE1, 0xFF, 0x02, 0x00, 0x00, 0x01, 0x00, 0x00},
                               Bytes{0xE0, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00}, Bytes{0xDE, 0x01, 0x00, 0x00}}) {
    line.transport.receive(line.frame(0, command));
  }
  const std::size_t responses = line.sent(1024).size();
  EXPECT_EQ(responses, 8U * 4U + 8U + 7U * 1U + 1U);  // 8 headers, CONNECT's 8 bytes, six 1-byte FFs and FF+PID
  line.slave.on_event(0);
  EXPECT_TRUE(line.sent(6).empty());                           // the frame needs 7 bytes: it waits
  EXPECT_EQ(line.sent(7), line.frame(8, {0x00, 0x01, 0x02}));  // ODT 0, two bytes; counter 8 follows the responses
}

TEST(StreamTransport, AResponseThatDoesNotFitTheQueueIsCounted) {
  Line line;
  for (int k = 0; k < 64; ++k) line.transport.receive(line.frame(0, {0xFF, 0x00}));      // nobody reads the answers
  const std::size_t answered = line.sent(4096).size() / line.frame(0, Bytes(8)).size();  // CONNECT's are 8 bytes
  EXPECT_GT(line.transport.responses_dropped(), 0U);
  EXPECT_EQ(answered + line.transport.responses_dropped(), 64U);
}

}  // namespace
}  // namespace duet::xcp
