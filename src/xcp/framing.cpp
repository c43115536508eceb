#include "duet/xcp/framing.hpp"

namespace duet::xcp {
namespace {

struct HeaderFields {
  std::size_t length = 0;
  std::uint16_t counter = 0;
};

HeaderFields read_header(const Framing& framing, std::span<const std::uint8_t> bytes) {
  switch (framing.header) {
    case FrameHeader::len_byte:
    case FrameHeader::len_fill_byte: return {bytes[0], 0};
    case FrameHeader::len_ctr_byte: return {bytes[0], bytes[1]};
    case FrameHeader::len_word:
    case FrameHeader::len_fill_word: return {static_cast<std::size_t>(bytes[0] | (bytes[1] << 8U)), 0};
    case FrameHeader::len_ctr_word:
      return {static_cast<std::size_t>(bytes[0] | (bytes[1] << 8U)),
              static_cast<std::uint16_t>(bytes[2] | (bytes[3] << 8U))};
  }
  return {};
}

// The checksum over header + packet (+ fill for a word checksum), as the tail carries it.
std::uint16_t frame_checksum(const Framing& framing, std::span<const std::uint8_t> covered) {
  if (framing.checksum == FrameChecksum::byte) {
    std::uint8_t sum = 0;
    for (std::uint8_t byte : covered) sum = static_cast<std::uint8_t>(sum + byte);
    return sum;
  }
  std::uint16_t sum = 0;  // little-endian words; an odd length ends with a fill byte of 0
  for (std::size_t offset = 0; offset < covered.size(); offset += 2) {
    const std::uint16_t high = offset + 1 < covered.size() ? covered[offset + 1] : 0;
    sum = static_cast<std::uint16_t>(sum + (covered[offset] | (high << 8U)));
  }
  return sum;
}

}  // namespace

std::size_t write_frame(const Framing& framing, std::span<std::uint8_t> frame, std::uint16_t counter,
                        std::span<const std::uint8_t> packet) {
  const std::size_t size = framing.frame_size(packet.size());
  if (packet.empty() || packet.size() > framing.max_packet() || size > frame.size()) return 0;
  const auto length = static_cast<std::uint16_t>(packet.size());
  std::size_t at = 0;
  auto put = [&](std::uint8_t byte) { frame[at++] = byte; };
  switch (framing.header) {
    case FrameHeader::len_byte: put(static_cast<std::uint8_t>(length)); break;
    case FrameHeader::len_ctr_byte:
      put(static_cast<std::uint8_t>(length));
      put(static_cast<std::uint8_t>(counter));
      break;
    case FrameHeader::len_fill_byte:
      put(static_cast<std::uint8_t>(length));
      put(0);
      break;
    case FrameHeader::len_word:
      put(static_cast<std::uint8_t>(length));
      put(static_cast<std::uint8_t>(length >> 8U));
      break;
    case FrameHeader::len_ctr_word:
      put(static_cast<std::uint8_t>(length));
      put(static_cast<std::uint8_t>(length >> 8U));
      put(static_cast<std::uint8_t>(counter));
      put(static_cast<std::uint8_t>(counter >> 8U));
      break;
    case FrameHeader::len_fill_word:
      put(static_cast<std::uint8_t>(length));
      put(static_cast<std::uint8_t>(length >> 8U));
      put(0);
      put(0);
      break;
  }
  for (std::uint8_t byte : packet) put(byte);
  if (framing.checksum == FrameChecksum::none) return at;
  if (framing.checksum == FrameChecksum::word && at % 2 != 0) put(0);  // the fill byte
  const std::uint16_t checksum = frame_checksum(framing, frame.first(at));
  put(static_cast<std::uint8_t>(checksum));
  if (framing.checksum == FrameChecksum::word) put(static_cast<std::uint8_t>(checksum >> 8U));
  return at;
}

FrameDecoder::Frame FrameDecoder::next_frame() {
  const std::size_t header_size = framing_.header_size();
  while (buffered() >= header_size) {
    const std::span<const std::uint8_t> held = std::span<const std::uint8_t>{buffer_}.subspan(begin_, buffered());
    const HeaderFields header = read_header(framing_, held.first(header_size));
    if (header.length == 0 || header.length > max_packet_ || framing_.frame_size(header.length) > buffer_.size()) {
      consume(1);
      ++dropped_;
      continue;
    }
    const std::size_t size = framing_.frame_size(header.length);
    if (held.size() < size) {
      if (begin_ + size > buffer_.size()) compact();  // make room for the rest of this frame
      return {};
    }
    if (framing_.checksum != FrameChecksum::none) {
      const std::size_t covered = framing_.checksum == FrameChecksum::word ? size - 2 : size - 1;
      const std::uint16_t expected = frame_checksum(framing_, held.first(covered));
      const std::uint16_t received = framing_.checksum == FrameChecksum::word
                                         ? static_cast<std::uint16_t>(held[size - 2] | (held[size - 1] << 8U))
                                         : held[size - 1];
      if (expected != received) {
        consume(1);
        ++dropped_;
        continue;
      }
    }
    return {size, header.length, header.counter};
  }
  if (begin_ + header_size > buffer_.size()) compact();
  return {};
}

bool FrameDecoder::holds_start_of_frame(std::uint16_t counter) const {
  if (!framing_.has_counter() || buffered() == 0) return false;
  const std::size_t length_size = framing_.header == FrameHeader::len_ctr_word ? 2 : 1;
  const std::size_t held = buffered() < framing_.header_size() ? buffered() : framing_.header_size();
  const std::uint8_t* const bytes = buffer_.data() + begin_;
  // The counter's bytes that have come (little-endian, after the length) are the counter's.
  for (std::size_t byte = length_size; byte < held; ++byte) {
    if (bytes[byte] != static_cast<std::uint8_t>(counter >> (8U * (byte - length_size)))) return false;
  }
  if (held < length_size) return true;  // part of the length only: any frame may begin so
  const std::size_t length = length_size == 2 ? static_cast<std::size_t>(bytes[0] | (bytes[1] << 8U)) : bytes[0];
  return length != 0 && length <= max_packet_ && framing_.frame_size(length) <= buffer_.size();
}

void FrameDecoder::compact() {
  const std::size_t held = buffered();
  for (std::size_t byte = 0; byte < held; ++byte) buffer_[byte] = buffer_[begin_ + byte];
  begin_ = 0;
  end_ = held;
}

}  // namespace duet::xcp
