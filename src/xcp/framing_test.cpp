#include "duet/xcp/framing.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace duet::xcp {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes frame(const Framing& framing, std::uint16_t counter, const Bytes& packet) {
  Bytes bytes(framing.frame_size(packet.size()) + 8);
  bytes.resize(write_frame(framing, bytes, counter, packet));
  return bytes;
}

struct Received {
  std::uint16_t counter;
  Bytes packet;
  bool operator==(const Received&) const = default;
};

// Feeds `stream` in pieces of random sizes (fixed seed) and returns what the decoder found.
std::vector<Received> decode(const Framing& framing, const Bytes& stream, std::size_t* dropped = nullptr) {
  std::array<std::uint8_t, 600> buffer{};
  FrameDecoder decoder{framing, buffer, 255};
  std::vector<Received> received;
  std::mt19937 random{42};
  std::size_t at = 0;
  while (at < stream.size()) {
    const std::size_t piece =
        std::min<std::size_t>(std::uniform_int_distribution<std::size_t>{1, 9}(random), stream.size() - at);
    decoder.feed(std::span{stream}.subspan(at, piece),
                 [&](std::uint16_t counter, std::span<const std::uint8_t> packet) {
                   received.push_back({counter, Bytes(packet.begin(), packet.end())});
                 });
    at += piece;
  }
  if (dropped != nullptr) *dropped = decoder.dropped_bytes();
  return received;
}

TEST(Framing, EthernetFramesAreLenCtrLittleEndian) {
  EXPECT_EQ(frame(ethernet_framing, 0x0102, {0xFF, 0x00}), (Bytes{0x02, 0x00, 0x02, 0x01, 0xFF, 0x00}));
  EXPECT_EQ(frame(ethernet_framing, 0, {}), Bytes{});  // no empty packets
}

TEST(Framing, SerialChecksumsFollowTheStandard) {
  // LEN_BYTE + byte checksum: 02 + FF + 00 = 0x101, the byte 01.
  EXPECT_EQ(frame({FrameHeader::len_byte, FrameChecksum::byte}, 0, {0xFF, 0x00}), (Bytes{0x02, 0xFF, 0x00, 0x01}));
  // LEN_WORD + word checksum: 3 bytes, so a fill byte; words 0x0001 + 0x00FF = 0x0100.
  EXPECT_EQ(frame({FrameHeader::len_word, FrameChecksum::word}, 0, {0xFF}),
            (Bytes{0x01, 0x00, 0xFF, 0x00, 0x00, 0x01}));
  EXPECT_EQ(frame({FrameHeader::len_ctr_byte, FrameChecksum::none}, 7, {0xFC}), (Bytes{0x01, 0x07, 0xFC}));
}

TEST(Framing, EveryHeaderAndChecksumRoundTripsInAnyPieces) {
  for (int header = 0; header <= 5; ++header) {
    for (int checksum = 0; checksum <= 2; ++checksum) {
      const Framing framing{static_cast<FrameHeader>(header), static_cast<FrameChecksum>(checksum)};
      const bool has_counter =
          framing.header == FrameHeader::len_ctr_byte || framing.header == FrameHeader::len_ctr_word;
      std::vector<Received> sent;
      Bytes stream;
      for (std::uint16_t counter = 1; counter <= 20; ++counter) {
        Bytes packet(static_cast<std::size_t>(counter * 7 % 40 + 1));
        for (std::size_t byte = 0; byte < packet.size(); ++byte)
          packet[byte] = static_cast<std::uint8_t>(counter + byte);
        const Bytes bytes = frame(framing, counter, packet);
        stream.insert(stream.end(), bytes.begin(), bytes.end());
        sent.push_back({static_cast<std::uint16_t>(has_counter ? counter : 0), packet});
      }
      EXPECT_EQ(decode(framing, stream), sent) << "header " << header << ", checksum " << checksum;
    }
  }
}

// Noise that looks like the header of a long frame holds the decoder up until that many bytes have come; then the
// checksum fails and the frames behind the noise are found in what was buffered. Nothing valid is lost.
TEST(Framing, TheDecoderFindsFramesAgainAfterGarbage) {
  const Framing framing{FrameHeader::len_ctr_word, FrameChecksum::word};
  Bytes stream{0x13, 0x37, 0x00, 0x00, 0xFF};  // noise, as from a link joined in the middle
  std::vector<Received> expected;
  for (std::uint16_t counter = 1; counter <= 15; ++counter) {
    Bytes bytes = frame(framing, counter, {0xFF, static_cast<std::uint8_t>(counter)});
    if (counter == 2) {
      bytes[4] ^= 0x01;  // a flipped bit: the checksum no longer matches and the frame is dropped
    } else {
      expected.push_back({counter, {0xFF, static_cast<std::uint8_t>(counter)}});
    }
    stream.insert(stream.end(), bytes.begin(), bytes.end());
  }
  std::size_t dropped = 0;
  EXPECT_EQ(decode(framing, stream, &dropped), expected);
  EXPECT_EQ(dropped, 5U + 8U);  // the noise and the damaged frame
}

// Without a checksum a lying header holds the decoder up until its frame is "complete"; a link that sends whole
// frames knows better after a quiet gap, and flush_stale() finds the real frames behind the lie.
TEST(Framing, AStalePartialFrameIsGivenUpAndTheFramesBehindItFound) {
  std::array<std::uint8_t, 600> buffer{};
  FrameDecoder decoder{ethernet_framing, buffer, 255};
  std::vector<Received> received;
  const auto collect = [&](std::uint16_t counter, std::span<const std::uint8_t> packet) {
    received.push_back({counter, Bytes(packet.begin(), packet.end())});
  };
  Bytes stream{0x40, 0x00, 0x00, 0x00};  // "64 bytes follow": they never do
  const Bytes good = frame(ethernet_framing, 5, {0xFF, 0x07});
  stream.insert(stream.end(), good.begin(), good.end());
  decoder.feed(stream, collect);
  EXPECT_TRUE(received.empty());
  EXPECT_EQ(decoder.buffered(), stream.size());
  decoder.flush_stale(collect);
  EXPECT_EQ(received, (std::vector<Received>{{5, {0xFF, 0x07}}}));
  EXPECT_EQ(decoder.buffered(), 0U);
  EXPECT_EQ(decoder.dropped_bytes(), 4U);
}

// A partial frame whose header carries the counter the sender is at is that sender's next frame, not garbage: what
// a link that pauses mid-frame (QEMU's UART, a byte at a time) asks the decoder about before giving it up. As much of
// the header as has come must agree; the first byte of a length alone agrees with any frame.
TEST(Framing, APartialFrameWithTheNextCounterIsTheSendersNextFrame) {
  std::array<std::uint8_t, 600> buffer{};
  const auto ignore = [](std::uint16_t, std::span<const std::uint8_t>) {};
  const Bytes next = frame(ethernet_framing, 0x1234, Bytes(40, 0xA5));  // 28 00 34 12 A5 ...
  for (const std::size_t held : {1U, 2U, 3U, 4U, 20U}) {
    FrameDecoder decoder{ethernet_framing, buffer, 255};
    EXPECT_FALSE(decoder.holds_start_of_frame(0x1234));  // nothing held
    decoder.feed(std::span{next}.first(held), ignore);
    EXPECT_TRUE(decoder.holds_start_of_frame(0x1234)) << held << " bytes";
    // Another counter: garbage that looks like a header, once a byte of the counter has come.
    EXPECT_EQ(decoder.holds_start_of_frame(0x1235), held < 3) << held << " bytes";
    EXPECT_EQ(decoder.holds_start_of_frame(0x1334), held < 4) << held << " bytes";
  }

  // A byte counter compares the counter's low byte; a framing without a counter never holds the next frame.
  const Framing byte_counter{FrameHeader::len_ctr_byte, FrameChecksum::byte};
  FrameDecoder serial{byte_counter, buffer, 255};
  const Bytes serial_frame = frame(byte_counter, 0x34, {0xFF, 0x00});
  serial.feed(std::span{serial_frame}.first(3), ignore);
  EXPECT_TRUE(serial.holds_start_of_frame(0x1234));
  EXPECT_FALSE(serial.holds_start_of_frame(0x1235));
  const Framing no_counter{FrameHeader::len_word, FrameChecksum::none};
  FrameDecoder plain{no_counter, buffer, 255};
  const Bytes plain_frame = frame(no_counter, 0, {0xFF, 0x00});
  plain.feed(std::span{plain_frame}.first(3), ignore);
  EXPECT_FALSE(plain.holds_start_of_frame(0));
}

// Ethernet framing has no checksum: a length of 0 or above the limit is what marks garbage.
TEST(Framing, LengthsOfZeroOrBeyondTheLimitAreGarbageToo) {
  Bytes stream{0x00, 0x00};  // length 0, then (shifted by one) length 0x0200, above 255
  const Bytes good = frame(ethernet_framing, 9, {0xFF, 0x01});
  stream.insert(stream.end(), good.begin(), good.end());
  EXPECT_EQ(decode(ethernet_framing, stream), (std::vector<Received>{{9, {0xFF, 0x01}}}));
}

}  // namespace
}  // namespace duet::xcp
