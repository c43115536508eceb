// The link's frames: every kind encoded and parsed back, the bytes on the wire as docs/LINK.md shows them, and the
// encoders' and parsers' refusals.
#include "duet/link/frame.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "duet/link/frame_decoder.hpp"

namespace duet::link {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes bytes_of(std::span<const std::uint8_t> frame) { return {frame.begin(), frame.end()}; }

// Decodes one whole frame, checking that it is exactly one.
struct Decoded {
  FrameKind kind{};
  Bytes payload;
};
Decoded decode_one(std::span<const std::uint8_t> frame) {
  FrameDecoder decoder;
  const auto fed = decoder.feed(frame);
  EXPECT_EQ(fed.status, DecodeStatus::frame);
  EXPECT_EQ(fed.used, frame.size());
  if (fed.status != DecodeStatus::frame) return {};
  return {decoder.kind(), bytes_of(decoder.payload())};
}

std::array<std::uint8_t, max_frame> buffer;

TEST(LinkFrame, HelloOnTheWire) {
  const auto frame = encode_hello(buffer, {protocol_version, LinkMode::real_time, 1'000'000});
  EXPECT_EQ(bytes_of(frame), (Bytes{0x01, 6, 0, 1, 1, 0x40, 0x42, 0x0F, 0x00}));
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::hello);
  Hello hello{0, LinkMode::lock_step, 0};
  ASSERT_EQ(parse(decoded.payload, hello), FrameError::none);
  EXPECT_EQ(hello.version, protocol_version);
  EXPECT_EQ(hello.mode, LinkMode::real_time);
  EXPECT_EQ(hello.base_period_ns, 1'000'000U);
}

TEST(LinkFrame, HelloOk) {
  const auto frame = encode_hello_ok(buffer, {protocol_version});
  EXPECT_EQ(bytes_of(frame), (Bytes{0x02, 1, 0, protocol_version}));
  HelloOk hello_ok{0};
  ASSERT_EQ(parse(decode_one(frame).payload, hello_ok), FrameError::none);
  EXPECT_EQ(hello_ok.version, protocol_version);
}

TEST(LinkFrame, WriteOnTheWire) {
  const double values[] = {1.0, -0.0};
  const auto frame = encode_write(buffer, "gpio:LED0", values);
  const Bytes expected{0x03, 28, 0, 9, 'g', 'p',  'i',  'o', ':', 'L', 'E', 'D', '0', 2, 0,   0,
                       0,    0,  0, 0, 0,   0xF0, 0x3F, 0,   0,   0,   0,   0,   0,   0, 0x80};
  EXPECT_EQ(bytes_of(frame), expected);
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::write);
  Write write;
  ASSERT_EQ(parse(decoded.payload, write), FrameError::none);
  EXPECT_EQ(write.resource, "gpio:LED0");
  ASSERT_EQ(write.values.size(), 2U);
  EXPECT_EQ(write.values[0], 1.0);
  EXPECT_TRUE(std::signbit(write.values[1]));
}

TEST(LinkFrame, DoublesTravelBitForBit) {
  const std::vector<double> values{0.1,
                                   -1e-310,  // subnormal
                                   std::numeric_limits<double>::infinity(),
                                   std::numeric_limits<double>::max(),
                                   std::bit_cast<double>(std::uint64_t{0x7FF8'0000'DEAD'BEEF}),  // a NaN's payload
                                   -0.0};
  const auto frame = encode_values(buffer, values);
  Values parsed;
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::values);
  ASSERT_EQ(parse(decoded.payload, parsed), FrameError::none);
  std::vector<double> back(values.size(), 7.0);
  parsed.values.copy_to(back);
  for (std::size_t k = 0; k < values.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back[k]), std::bit_cast<std::uint64_t>(values[k])) << k;
  }
}

TEST(LinkFrame, Read) {
  const auto frame = encode_read(buffer, "adc:ADC1/6", 3);
  EXPECT_EQ(frame.size(), header_size + 1 + 10 + 2);
  Read read;
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::read);
  ASSERT_EQ(parse(decoded.payload, read), FrameError::none);
  EXPECT_EQ(read.resource, "adc:ADC1/6");
  EXPECT_EQ(read.count, 3U);
}

TEST(LinkFrame, TickCarriesTheTimeExactly) {
  // Tick 9 at 1 ms is 9 * 0.001 = 0.009000000000000001 in a simulation: a count of nanoseconds would arrive as 0.009.
  const double time = 9 * 0.001;
  EXPECT_NE(time, 9'000'000 / 1e9);
  const auto frame = encode_tick(buffer, time);
  EXPECT_EQ(frame.size(), header_size + 8);
  Tick tick;
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::tick);
  ASSERT_EQ(parse(decoded.payload, tick), FrameError::none);
  EXPECT_EQ(std::bit_cast<std::uint64_t>(tick.time_s), std::bit_cast<std::uint64_t>(time));
}

TEST(LinkFrame, InterruptAndTheEmptyOnes) {
  const auto frame = encode_interrupt(buffer, "EXTI0");
  EXPECT_EQ(bytes_of(frame), (Bytes{0x07, 6, 0, 5, 'E', 'X', 'T', 'I', '0'}));
  Interrupt interrupt;
  const Decoded decoded = decode_one(frame);  // the name points into its payload
  ASSERT_EQ(parse(decoded.payload, interrupt), FrameError::none);
  EXPECT_EQ(interrupt.name, "EXTI0");
  for (const FrameKind kind : {FrameKind::interrupt_done, FrameKind::tick_done, FrameKind::bye}) {
    const auto empty = encode_empty(buffer, kind);
    EXPECT_EQ(bytes_of(empty), (Bytes{static_cast<std::uint8_t>(kind), 0, 0}));
    EXPECT_EQ(decode_one(empty).kind, kind);
  }
}

TEST(LinkFrame, ErrorTextIsCutAtACharacterBoundary) {
  const auto frame = encode_error(buffer, "the plant is on fire");
  ErrorText text;
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::error);
  ASSERT_EQ(parse(decoded.payload, text), FrameError::none);
  EXPECT_EQ(text.text, "the plant is on fire");
  std::array<std::uint8_t, header_size + 3> small{};
  const auto cut = encode_error(small, "ab\xC3\xA9z");  // "abéz": é is two bytes, the 3rd and 4th
  EXPECT_EQ(bytes_of(cut), (Bytes{0x0A, 2, 0, 'a', 'b'}));
  const std::string long_text(max_payload + 10, 'x');
  EXPECT_EQ(encode_error(buffer, long_text).size(), max_frame);
}

TEST(LinkFrame, EncodersRefuseWhatDoesNotFit) {
  EXPECT_TRUE(encode_interrupt(buffer, "").empty());
  EXPECT_TRUE(encode_interrupt(buffer, std::string(max_name + 1, 'n')).empty());
  EXPECT_FALSE(encode_interrupt(buffer, std::string(max_name, 'n')).empty());
  // The most a WRITE with the longest name holds, and one more.
  const std::vector<double> most(max_values, 1.5);
  const std::vector<double> too_many(max_values + 1, 1.5);
  EXPECT_EQ(encode_write(buffer, std::string(max_name, 'r'), most).size(),
            header_size + 1 + 255 + 2 + std::size_t{479} * 8);
  EXPECT_TRUE(encode_write(buffer, std::string(max_name, 'r'), too_many).empty());
  EXPECT_EQ(encode_values(buffer, std::vector<double>(max_read_values, 0.0)).size(),
            header_size + 2 + std::size_t{511} * 8);
  EXPECT_TRUE(encode_values(buffer, std::vector<double>(max_read_values + 1, 0.0)).empty());
  std::array<std::uint8_t, 10> small{};
  EXPECT_TRUE(encode_tick(small, 1.0).empty());  // 11 bytes
  EXPECT_TRUE(encode_empty(std::span<std::uint8_t>{small}.first(2), FrameKind::bye).empty());
}

TEST(LinkFrame, ParsersSayWhatIsWrong) {
  Hello hello;
  EXPECT_EQ(parse(Bytes{1, 2, 0, 0, 0, 0}, hello), FrameError::bad_mode);
  EXPECT_EQ(parse(Bytes{1, 0, 0}, hello), FrameError::wrong_length);
  Write write;
  EXPECT_EQ(parse(Bytes{0, 0, 0, 0}, write), FrameError::bad_name);
  EXPECT_EQ(parse(Bytes{5, 'a', 'b'}, write), FrameError::wrong_length);  // the name runs past the end
  EXPECT_EQ(parse(Bytes{1, 'a', 2, 0, 1, 2, 3, 4, 5, 6, 7, 8}, write), FrameError::bad_count);  // 2 said, 1 there
  EXPECT_EQ(parse(Bytes{1, 'a', 0}, write), FrameError::wrong_length);                          // half a count
  Read read;
  EXPECT_EQ(parse(Bytes{1, 'a', 1, 0, 9}, read), FrameError::wrong_length);  // a byte too many
  Values values;
  EXPECT_EQ(parse(Bytes{1, 0, 0, 0}, values), FrameError::bad_count);
  Interrupt interrupt;
  EXPECT_EQ(parse(Bytes{1, 'a', 'b'}, interrupt), FrameError::wrong_length);
  EXPECT_EQ(parse(Bytes{0}, interrupt), FrameError::bad_name);
  Tick tick;
  EXPECT_EQ(parse(Bytes{1, 2, 3}, tick), FrameError::wrong_length);
}

TEST(LinkFrame, KindsHaveNamesAndFixedLengths) {
  for (std::uint8_t byte = 0; byte < 0x20; ++byte) {
    EXPECT_EQ(is_frame_kind(byte), byte >= 1 && byte <= 11) << int{byte};
  }
  EXPECT_STREQ(kind_name(FrameKind::interrupt_done), "INTERRUPT_DONE");
  EXPECT_EQ(fixed_payload(FrameKind::hello), 6);
  EXPECT_EQ(fixed_payload(FrameKind::write), -1);
  EXPECT_EQ(min_payload(FrameKind::write), 4U);
  EXPECT_STREQ(describe(FrameError::bad_count), "value count does not match the payload length");
}

}  // namespace
}  // namespace duet::link
