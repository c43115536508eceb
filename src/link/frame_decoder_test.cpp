// The frame decoder: frames in any pieces, and garbage of every kind refused with a reason, never overflowing,
// hanging or crashing (these tests run under AddressSanitizer and UndefinedBehaviorSanitizer).
#include "duet/link/frame_decoder.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <vector>

#include "duet/link/frame.hpp"

namespace duet::link {
namespace {

using Bytes = std::vector<std::uint8_t>;

struct Event {
  DecodeStatus status;
  FrameKind kind{};
  Bytes payload;
  FrameError error = FrameError::none;
  bool operator==(const Event&) const = default;
};

// Feeds `stream` in pieces whose sizes `piece` chooses; what the decoder reported, in order, up to its first error.
template <std::size_t Capacity, typename Piece>
std::vector<Event> decode(BasicFrameDecoder<Capacity>& decoder, const Bytes& stream, Piece&& piece) {
  std::vector<Event> events;
  std::size_t at = 0;
  std::size_t stuck = 0;
  while (at < stream.size()) {
    const std::size_t size = std::min<std::size_t>(piece(), stream.size() - at);
    std::span<const std::uint8_t> rest{stream.data() + at, size};
    while (!rest.empty()) {
      const auto fed = decoder.feed(rest);
      EXPECT_LE(fed.used, rest.size());
      rest = rest.subspan(fed.used);
      at += fed.used;
      if (fed.status == DecodeStatus::frame) {
        EXPECT_LE(decoder.payload().size(), Capacity);
        events.push_back({fed.status, decoder.kind(), Bytes(decoder.payload().begin(), decoder.payload().end())});
      } else if (fed.status == DecodeStatus::error) {
        EXPECT_NE(decoder.error(), FrameError::none);
        events.push_back({fed.status, {}, {}, decoder.error()});
        return events;
      } else {
        EXPECT_TRUE(rest.empty()) << "need_more with bytes left";
      }
      if (fed.used == 0 && ++stuck > 2) {
        ADD_FAILURE() << "the decoder takes nothing";
        return events;
      }
    }
  }
  return events;
}

Bytes concatenate(std::initializer_list<std::span<const std::uint8_t>> frames) {
  Bytes all;
  for (const auto frame : frames) all.insert(all.end(), frame.begin(), frame.end());
  return all;
}

Bytes sample_frames() {
  std::array<std::uint8_t, max_frame> a{};
  std::array<std::uint8_t, max_frame> b{};
  std::array<std::uint8_t, max_frame> c{};
  std::array<std::uint8_t, max_frame> d{};
  std::array<std::uint8_t, max_frame> e{};
  std::array<std::uint8_t, max_frame> f{};
  const float duties[] = {0.25F, -3.0F, 1e30F};
  const std::uint16_t samples[] = {1, 2013, 0xFFFF};
  return concatenate({encode_hello(a, {protocol_version, LinkMode::lock_step, 1000}), encode_tick(b, 500),
                      encode_write(c, "pwm:TIM1/1", std::span<const float>{duties}), encode_empty(d, FrameKind::bye),
                      encode_read(e, "adc:ADC1/6", ElementType::u16, 3),
                      encode_values(f, std::span<const std::uint16_t>{samples})});
}

TEST(LinkFrameDecoder, FramesInAnyPiecesGiveTheSameFrames) {
  const Bytes stream = sample_frames();
  FrameDecoder whole;
  const std::vector<Event> expected = decode(whole, stream, [&] { return stream.size(); });
  ASSERT_EQ(expected.size(), 6U);
  EXPECT_EQ(expected[0].kind, FrameKind::hello);
  EXPECT_EQ(expected[3].kind, FrameKind::bye);
  EXPECT_TRUE(expected[3].payload.empty());
  EXPECT_EQ(expected[4].kind, FrameKind::read);
  EXPECT_EQ(expected[5].kind, FrameKind::values);
  FrameDecoder byte_by_byte;
  EXPECT_EQ(decode(byte_by_byte, stream, [] { return std::size_t{1}; }), expected);
  std::mt19937 random{7};
  for (int run = 0; run < 200; ++run) {
    FrameDecoder pieces;
    EXPECT_EQ(decode(pieces, stream,
                     [&] {
                       return std::uniform_int_distribution<std::size_t>{1, 40}(random);
                     }),
              expected);
  }
}

TEST(LinkFrameDecoder, PushOneByteAtATime) {
  const Bytes stream = sample_frames();
  FrameDecoder decoder;
  int frames = 0;
  for (const std::uint8_t byte : stream) {
    const DecodeStatus status = decoder.push(byte);
    ASSERT_NE(status, DecodeStatus::error);
    if (status == DecodeStatus::frame) {
      ++frames;
      EXPECT_EQ(decoder.partial(), 0U);
    } else {
      EXPECT_GT(decoder.partial(), 0U);
    }
  }
  EXPECT_EQ(frames, 6);
}

TEST(LinkFrameDecoder, AnUnknownKindIsRefusedAtItsFirstByte) {
  for (const std::uint8_t kind : std::array<std::uint8_t, 4>{0x00, 0x0C, 0x55, 0xFF}) {
    FrameDecoder decoder;
    EXPECT_EQ(decoder.push(kind), DecodeStatus::error);
    EXPECT_EQ(decoder.error(), FrameError::unknown_kind);
    EXPECT_EQ(decoder.partial_kind(), kind);
    // It stays refused: nothing more is taken until reset().
    const Bytes more{0x0B, 0, 0};
    EXPECT_EQ(decoder.feed(more).used, 0U);
    EXPECT_EQ(decoder.feed(more).status, DecodeStatus::error);
    decoder.reset();
    EXPECT_EQ(decoder.feed(more).status, DecodeStatus::frame);
  }
}

TEST(LinkFrameDecoder, LengthsOverTheBufferOrWrongForTheKind) {
  FrameDecoder decoder;
  const Bytes too_long{0x03, 0x01, 0x10};  // WRITE of 4097 bytes
  EXPECT_EQ(decoder.feed(too_long).status, DecodeStatus::error);
  EXPECT_EQ(decoder.error(), FrameError::payload_too_long);
  EXPECT_EQ(decoder.announced(), 4097U);

  BasicFrameDecoder<64> small;
  EXPECT_EQ(small.feed(Bytes{0x05, 65, 0}).status, DecodeStatus::error);  // over this decoder's 64 bytes
  EXPECT_EQ(small.error(), FrameError::payload_too_long);

  for (const Bytes& header : {Bytes{0x06, 7, 0}, Bytes{0x01, 0, 0}, Bytes{0x0B, 1, 0}, Bytes{0x03, 4, 0},
                              Bytes{0x04, 4, 0}, Bytes{0x07, 1, 0}, Bytes{0x05, 2, 0}, Bytes{0x02, 2, 0}}) {
    decoder.reset();
    const auto fed = decoder.feed(header);
    EXPECT_EQ(fed.status, DecodeStatus::error) << int{header[0]};
    EXPECT_EQ(fed.used, 3U);
    EXPECT_EQ(decoder.error(), FrameError::wrong_length) << int{header[0]};
  }
}

TEST(LinkFrameDecoder, ATruncatedFrameWaitsAndSaysHowMuchItHas) {
  std::array<std::uint8_t, max_frame> buffer{};
  const auto frame = encode_tick(buffer, 1.0);
  FrameDecoder decoder;
  const auto fed = decoder.feed(frame.first(7));
  EXPECT_EQ(fed.status, DecodeStatus::need_more);
  EXPECT_EQ(fed.used, 7U);
  EXPECT_EQ(decoder.partial(), 7U);
  EXPECT_EQ(decoder.announced(), 8U);
  EXPECT_EQ(decoder.partial_kind(), 0x06);
  EXPECT_EQ(decoder.feed(frame.subspan(7)).status, DecodeStatus::frame);
  EXPECT_EQ(decoder.partial(), 0U);
  EXPECT_EQ(decoder.feed({}).status, DecodeStatus::frame);  // feeding nothing keeps the frame
  EXPECT_EQ(decoder.payload().size(), 8U);
}

// Random garbage, 10,000 streams from a fixed seed: some made of nothing but random bytes, some of valid frames
// with bytes changed, cut or inserted. The decoder must always come to an end, within its buffer, and report either
// frames whose header is sound or an error. Random bytes are refused almost at once (the kind byte alone is wrong
// 244 times in 256), so most streams must end in an error.
TEST(LinkFrameDecoder, TenThousandGarbageStreams) {
  std::mt19937_64 random{20240611};
  const Bytes valid = sample_frames();
  int errors = 0;
  int frames = 0;
  int mismatched_splits = 0;
  for (int run = 0; run < 10'000; ++run) {
    Bytes stream;
    if (run % 2 == 0) {
      stream.resize(std::uniform_int_distribution<std::size_t>{1, 300}(random));
      for (std::uint8_t& byte : stream) byte = static_cast<std::uint8_t>(random());
    } else {
      stream = valid;
      const int changes = std::uniform_int_distribution<int>{1, 4}(random);
      for (int change = 0; change < changes; ++change) {
        const std::size_t at = std::uniform_int_distribution<std::size_t>{0, stream.size() - 1}(random);
        switch (random() % 3) {
          case 0: stream[at] = static_cast<std::uint8_t>(random()); break;
          case 1: stream.resize(at + 1); break;
          default: stream.insert(stream.begin() + static_cast<std::ptrdiff_t>(at), static_cast<std::uint8_t>(random()));
        }
      }
    }
    FrameDecoder whole;
    const std::vector<Event> events = decode(whole, stream, [&] { return stream.size(); });
    FrameDecoder split;
    const std::vector<Event> split_events = decode(split, stream, [&] {
      return std::uniform_int_distribution<std::size_t>{1, 9}(random);
    });
    if (split_events != events) ++mismatched_splits;
    for (const Event& event : events) {
      if (event.status == DecodeStatus::error) {
        ++errors;
      } else {
        ++frames;
        const int fixed = fixed_payload(event.kind);
        EXPECT_TRUE(fixed < 0 || event.payload.size() == static_cast<std::size_t>(fixed));
        EXPECT_GE(event.payload.size(), min_payload(event.kind));
        // The parsers take whatever the decoder let through without reading past it.
        Write write;
        Read read;
        Values values;
        Interrupt interrupt;
        Hello hello;
        // Every element of what parsed is read: a count the parser let through that runs past the payload would be
        // a read out of bounds, which AddressSanitizer reports.
        if (parse(event.payload, write) == FrameError::none) {
          for (std::size_t k = 0; k < write.values.size(); ++k) (void)write.values.bits(k);
        }
        (void)parse(event.payload, read);
        if (parse(event.payload, values) == FrameError::none) {
          for (std::size_t k = 0; k < values.values.size(); ++k) (void)values.values.bits(k);
        }
        (void)parse(event.payload, interrupt);
        (void)parse(event.payload, hello);
      }
    }
  }
  EXPECT_EQ(mismatched_splits, 0);
  EXPECT_GT(errors, 5'000);
  EXPECT_GT(frames, 5'000);
}

}  // namespace
}  // namespace duet::link
