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

// The expected bytes below are written from docs/LINK.md's tables (frames, element types), not taken from the
// encoder.
TEST(LinkFrame, HelloOnTheWire) {
  const auto frame = encode_hello(buffer, {protocol_version, LinkMode::real_time, 1'000'000});
  EXPECT_EQ(bytes_of(frame), (Bytes{0x01, 6, 0, 2, 1, 0x40, 0x42, 0x0F, 0x00}));
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::hello);
  Hello hello{0, LinkMode::lock_step, 0};
  ASSERT_EQ(parse(decoded.payload, hello), FrameError::none);
  EXPECT_EQ(hello.version, 2U);
  EXPECT_EQ(hello.mode, LinkMode::real_time);
  EXPECT_EQ(hello.base_period_ns, 1'000'000U);
}

TEST(LinkFrame, AVersion1HelloStillParsesSoThatItsVersionCanBeRefused) {
  Hello hello;
  ASSERT_EQ(parse(Bytes{1, 0, 0x40, 0x42, 0x0F, 0x00}, hello), FrameError::none);
  EXPECT_EQ(hello.version, 1U);
}

TEST(LinkFrame, HelloOk) {
  const auto frame = encode_hello_ok(buffer, {protocol_version});
  EXPECT_EQ(bytes_of(frame), (Bytes{0x02, 1, 0, 2}));
  HelloOk hello_ok{0};
  ASSERT_EQ(parse(decode_one(frame).payload, hello_ok), FrameError::none);
  EXPECT_EQ(hello_ok.version, 2U);
}

TEST(LinkFrame, WriteOfBoolsOnTheWire) {
  const bool levels[] = {true, false};
  const auto frame = encode_write(buffer, "gpio:LED0", std::span<const bool>{levels});
  EXPECT_EQ(bytes_of(frame),
            (Bytes{0x03, 0x0F, 0, 9, 'g', 'p', 'i', 'o', ':', 'L', 'E', 'D', '0', 0x01, 2, 0, 0x01, 0x00}));
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::write);
  Write write;
  ASSERT_EQ(parse(decoded.payload, write), FrameError::none);
  EXPECT_EQ(write.resource, "gpio:LED0");
  EXPECT_EQ(write.values.type(), ElementType::boolean);
  ASSERT_EQ(write.values.size(), 2U);
  EXPECT_TRUE(write.values.at<bool>(0));
  EXPECT_FALSE(write.values.at<bool>(1));
}

TEST(LinkFrame, WriteOfBytesAndOfAFloatOnTheWire) {
  const std::uint8_t bytes[] = {0x6B, 0x80};
  EXPECT_EQ(bytes_of(encode_write(buffer, "spi:SPI5", std::span<const std::uint8_t>{bytes})),
            (Bytes{0x03, 0x0E, 0, 8, 's', 'p', 'i', ':', 'S', 'P', 'I', '5', 0x02, 2, 0, 0x6B, 0x80}));
  const float duty[] = {0.4F};  // binary32 0x3ECCCCCD
  const auto frame = encode_write(buffer, "pwm:TIM1/3", std::span<const float>{duty});
  EXPECT_EQ(bytes_of(frame), (Bytes{0x03, 0x12, 0,   10,   'p', 'w', 'm',  ':',  'T',  'I', 'M',
                                    '1',  '/',  '3', 0x05, 1,   0,   0xCD, 0xCC, 0xCC, 0x3E}));
  Write write;
  const Decoded decoded = decode_one(frame);  // the parsed values point into its payload
  ASSERT_EQ(parse(decoded.payload, write), FrameError::none);
  EXPECT_EQ(write.values.type(), ElementType::f32);
  EXPECT_EQ(write.values.at<float>(0), 0.4F);
}

TEST(LinkFrame, ValuesOfEachIntegerTypeOnTheWire) {
  const std::uint16_t samples[] = {2013, 0xFFFF};
  EXPECT_EQ(bytes_of(encode_values(buffer, std::span<const std::uint16_t>{samples})),
            (Bytes{0x05, 7, 0, 0x03, 2, 0, 0xDD, 0x07, 0xFF, 0xFF}));
  const std::uint32_t counts[] = {70'000, 1};
  const auto frame = encode_values(buffer, std::span<const std::uint32_t>{counts});
  EXPECT_EQ(bytes_of(frame), (Bytes{0x05, 0x0B, 0, 0x04, 2, 0, 0x70, 0x11, 0x01, 0x00, 0x01, 0x00, 0x00, 0x00}));
  Values values;
  const Decoded decoded = decode_one(frame);
  ASSERT_EQ(parse(decoded.payload, values), FrameError::none);
  std::uint32_t back[2]{};
  values.values.copy_to(std::span<std::uint32_t>{back});
  EXPECT_EQ(back[0], 70'000U);
  EXPECT_EQ(back[1], 1U);
}

TEST(LinkFrame, ValuesOfDoublesOnTheWire) {
  const double values[] = {1.0, -0.0};
  EXPECT_EQ(bytes_of(encode_values(buffer, std::span<const double>{values})),
            (Bytes{0x05, 0x13, 0, 0x06, 2, 0, 0, 0, 0, 0, 0, 0, 0xF0, 0x3F, 0, 0, 0, 0, 0, 0, 0, 0x80}));
}

TEST(LinkFrame, FloatsTravelBitForBit) {
  const std::vector<double> doubles{0.1,
                                    -1e-310,  // subnormal
                                    std::numeric_limits<double>::infinity(),
                                    std::numeric_limits<double>::max(),
                                    std::bit_cast<double>(std::uint64_t{0x7FF8'0000'DEAD'BEEF}),  // a NaN's payload
                                    -0.0};
  Values parsed;
  const Decoded decoded_doubles = decode_one(encode_values(buffer, std::span<const double>{doubles}));
  ASSERT_EQ(parse(decoded_doubles.payload, parsed), FrameError::none);
  std::vector<double> back(doubles.size(), 7.0);
  parsed.values.copy_to(std::span<double>{back});
  for (std::size_t k = 0; k < doubles.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(back[k]), std::bit_cast<std::uint64_t>(doubles[k])) << k;
  }
  const std::vector<float> floats{0.1F, -1e-40F, std::bit_cast<float>(std::uint32_t{0x7FC0'BEEF}), -0.0F};
  const Decoded decoded_floats = decode_one(encode_values(buffer, std::span<const float>{floats}));
  ASSERT_EQ(parse(decoded_floats.payload, parsed), FrameError::none);
  for (std::size_t k = 0; k < floats.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(parsed.values.at<float>(k)), std::bit_cast<std::uint32_t>(floats[k])) << k;
  }
}

TEST(LinkFrame, ReadAsksForAType) {
  const auto frame = encode_read(buffer, "adc:ADC1/6", ElementType::u16, 100);
  EXPECT_EQ(bytes_of(frame),
            (Bytes{0x04, 0x0E, 0, 10, 'a', 'd', 'c', ':', 'A', 'D', 'C', '1', '/', '6', 0x03, 100, 0}));
  Read read;
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::read);
  ASSERT_EQ(parse(decoded.payload, read), FrameError::none);
  EXPECT_EQ(read.resource, "adc:ADC1/6");
  EXPECT_EQ(read.type, ElementType::u16);
  EXPECT_EQ(read.count, 100U);
}

TEST(LinkFrame, TickCarriesTheTicksNumber) {
  EXPECT_EQ(bytes_of(encode_tick(buffer, 9)), (Bytes{0x06, 8, 0, 9, 0, 0, 0, 0, 0, 0, 0}));
  const auto frame = encode_tick(buffer, 0x0102'0304'0506'0708ULL);
  EXPECT_EQ(bytes_of(frame), (Bytes{0x06, 8, 0, 0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01}));
  Tick tick;
  const Decoded decoded = decode_one(frame);
  EXPECT_EQ(decoded.kind, FrameKind::tick);
  ASSERT_EQ(parse(decoded.payload, tick), FrameError::none);
  EXPECT_EQ(tick.tick, 0x0102'0304'0506'0708ULL);
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
  // The most f64 a WRITE with the longest name holds ((4096 - 259) / 8 = 479), and one more; as many u8 elements.
  EXPECT_EQ(max_write_count(ElementType::f64), 479U);
  EXPECT_EQ(max_write_count(ElementType::u8), 3837U);
  const std::vector<double> most(479, 1.5);
  const std::vector<double> too_many(480, 1.5);
  EXPECT_EQ(encode_write(buffer, std::string(max_name, 'r'), std::span<const double>{most}).size(),
            header_size + 1 + 255 + 1 + 2 + std::size_t{479} * 8);
  EXPECT_TRUE(encode_write(buffer, std::string(max_name, 'r'), std::span<const double>{too_many}).empty());
  // A VALUES holds (4096 - 3) / size elements: 511 f64, 4093 u8.
  EXPECT_EQ(max_read_count(ElementType::f64), 511U);
  EXPECT_EQ(max_read_count(ElementType::u8), 4093U);
  const std::vector<double> doubles(512, 0.0);
  EXPECT_EQ(encode_values(buffer, std::span<const double>{doubles}.first(511)).size(), header_size + 3 + 511 * 8);
  EXPECT_TRUE(encode_values(buffer, std::span<const double>{doubles}).empty());
  const std::vector<std::uint8_t> bytes(4094, 0);
  EXPECT_EQ(encode_values(buffer, std::span<const std::uint8_t>{bytes}.first(4093)).size(), max_frame);
  EXPECT_TRUE(encode_values(buffer, std::span<const std::uint8_t>{bytes}).empty());
  std::array<std::uint8_t, 10> small{};
  EXPECT_TRUE(encode_tick(small, 1).empty());  // 11 bytes
  EXPECT_TRUE(encode_empty(std::span<std::uint8_t>{small}.first(2), FrameKind::bye).empty());
}

TEST(LinkFrame, ParsersSayWhatIsWrong) {
  Hello hello;
  EXPECT_EQ(parse(Bytes{2, 2, 0, 0, 0, 0}, hello), FrameError::bad_mode);
  EXPECT_EQ(parse(Bytes{2, 0, 0}, hello), FrameError::wrong_length);
  Write write;
  EXPECT_EQ(parse(Bytes{0, 0x02, 0, 0, 0}, write), FrameError::bad_name);
  EXPECT_EQ(parse(Bytes{5, 'a', 'b'}, write), FrameError::wrong_length);            // the name runs past the end
  EXPECT_EQ(parse(Bytes{1, 'a', 0x03, 2, 0, 1, 2}, write), FrameError::bad_count);  // 2 u16 said, 1 there
  EXPECT_EQ(parse(Bytes{1, 'a', 0x02, 0}, write), FrameError::wrong_length);        // half a count
  EXPECT_EQ(parse(Bytes{1, 'a'}, write), FrameError::wrong_length);                 // no element type
  EXPECT_EQ(parse(Bytes{1, 'a', 0x00, 0, 0}, write), FrameError::bad_element_type);
  EXPECT_EQ(parse(Bytes{1, 'a', 0x07, 0, 0}, write), FrameError::bad_element_type);
  EXPECT_EQ(parse(Bytes{1, 'a', 0x01, 1, 0, 0x02}, write), FrameError::bad_boolean);
  Read read;
  EXPECT_EQ(parse(Bytes{1, 'a', 0x02, 1, 0, 9}, read), FrameError::wrong_length);  // a byte too many
  EXPECT_EQ(parse(Bytes{1, 'a', 0x09, 1, 0}, read), FrameError::bad_element_type);
  Values values;
  EXPECT_EQ(parse(Bytes{0x06, 1, 0, 0}, values), FrameError::bad_count);
  EXPECT_EQ(parse(Bytes{0x01, 1, 0, 0xFF}, values), FrameError::bad_boolean);
  EXPECT_EQ(parse(Bytes{0xEE, 0, 0}, values), FrameError::bad_element_type);
  Interrupt interrupt;
  EXPECT_EQ(parse(Bytes{1, 'a', 'b'}, interrupt), FrameError::wrong_length);
  EXPECT_EQ(parse(Bytes{0}, interrupt), FrameError::bad_name);
  Tick tick;
  EXPECT_EQ(parse(Bytes{1, 2, 3}, tick), FrameError::wrong_length);
}

TEST(LinkFrame, KindsAndElementTypesHaveNamesAndSizes) {
  for (std::uint8_t byte = 0; byte < 0x20; ++byte) {
    EXPECT_EQ(is_frame_kind(byte), byte >= 1 && byte <= 11) << int{byte};
    EXPECT_EQ(is_element_type(byte), byte >= 1 && byte <= 6) << int{byte};
  }
  EXPECT_EQ(kind_name(FrameKind::interrupt_done), "INTERRUPT_DONE");
  EXPECT_EQ(fixed_payload(FrameKind::hello), 6);
  EXPECT_EQ(fixed_payload(FrameKind::tick), 8);
  EXPECT_EQ(fixed_payload(FrameKind::write), -1);
  EXPECT_EQ(min_payload(FrameKind::write), 5U);
  EXPECT_EQ(min_payload(FrameKind::read), 5U);
  EXPECT_EQ(min_payload(FrameKind::values), 3U);
  EXPECT_EQ(describe(FrameError::bad_count), "value count does not match the payload length");
  EXPECT_EQ(element_type_name(ElementType::f32), "f32");
  const std::size_t sizes[] = {1, 1, 2, 4, 4, 8};  // bool, u8, u16, u32, f32, f64
  for (std::uint8_t byte = 1; byte <= 6; ++byte) {
    EXPECT_EQ(element_size(static_cast<ElementType>(byte)), sizes[byte - 1]) << int{byte};
  }
}

}  // namespace
}  // namespace duet::link
