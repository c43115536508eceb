#pragma once
// How XCP packets travel on a byte stream or in datagrams: a header with the packet's length (and maybe a counter)
// before each packet, and on serial links maybe a checksum after it. XCP on Ethernet (TCP and UDP) is the header
// LEN u16, CTR u16 without a checksum, which is XCP on SxI's LEN_CTR_WORD: one implementation serves both.
// Freestanding: the firmware frames with it, the bridge and the master parse with it.

#include <cstddef>
#include <cstdint>
#include <span>

namespace duet::xcp {

// SxI header types (their A2L enum values) and tails.
enum class FrameHeader : std::uint8_t {
  len_byte = 0,
  len_ctr_byte = 1,
  len_fill_byte = 2,
  len_word = 3,
  len_ctr_word = 4,
  len_fill_word = 5,
};
enum class FrameChecksum : std::uint8_t { none = 0, byte = 1, word = 2 };

struct Framing {
  FrameHeader header = FrameHeader::len_ctr_word;
  FrameChecksum checksum = FrameChecksum::none;

  [[nodiscard]] constexpr std::size_t header_size() const {
    return header == FrameHeader::len_byte                                               ? 1
           : header == FrameHeader::len_ctr_byte || header == FrameHeader::len_fill_byte ? 2
           : header == FrameHeader::len_word                                             ? 2
                                                                                         : 4;
  }
  // Bytes after the packet: the checksum, and for a word checksum a fill byte when header + packet is odd.
  [[nodiscard]] constexpr std::size_t tail_size(std::size_t packet_size) const {
    if (checksum == FrameChecksum::none) return 0;
    if (checksum == FrameChecksum::byte) return 1;
    return ((header_size() + packet_size) % 2 != 0 ? 1 : 0) + 2;
  }
  [[nodiscard]] constexpr std::size_t frame_size(std::size_t packet_size) const {
    return header_size() + packet_size + tail_size(packet_size);
  }
  // Whether the header carries the sender's counter (CTR), a byte or a word of it.
  [[nodiscard]] constexpr bool has_counter() const {
    return header == FrameHeader::len_ctr_byte || header == FrameHeader::len_ctr_word;
  }
  [[nodiscard]] constexpr std::size_t max_packet() const {
    return header == FrameHeader::len_byte || header == FrameHeader::len_ctr_byte ||
                   header == FrameHeader::len_fill_byte
               ? 0xFF
               : 0xFFFF;
  }
};

inline constexpr Framing ethernet_framing{FrameHeader::len_ctr_word, FrameChecksum::none};

// Writes one frame (header, packet, tail) into `frame`; returns its size, or 0 if it does not fit or the packet is
// empty or too long for the header.
std::size_t write_frame(const Framing& framing, std::span<std::uint8_t> frame, std::uint16_t counter,
                        std::span<const std::uint8_t> packet);

// Splits a byte stream into packets, whatever pieces the bytes arrive in. A header whose length is 0 or larger than
// `max_packet`, or a frame whose checksum is wrong, is garbage: the decoder drops one byte and looks again, so it
// finds the frames again after noise or after joining a stream in the middle.
class FrameDecoder {
 public:
  // `buffer` must hold the largest frame: framing.frame_size(max_packet).
  FrameDecoder(const Framing& framing, std::span<std::uint8_t> buffer, std::size_t max_packet)
      : framing_(framing), buffer_(buffer), max_packet_(max_packet) {}

  // Feeds received bytes; calls `on_packet(counter, packet)` for each complete, valid frame, in order.
  template <typename OnPacket>
  void feed(std::span<const std::uint8_t> bytes, OnPacket&& on_packet) {
    while (!bytes.empty()) {
      if (end_ == buffer_.size()) compact();
      const std::size_t room = buffer_.size() - end_;
      const std::size_t taken = bytes.size() < room ? bytes.size() : room;
      for (std::size_t byte = 0; byte < taken; ++byte) buffer_[end_ + byte] = bytes[byte];
      end_ += taken;
      bytes = bytes.subspan(taken);
      deliver(on_packet);
    }
  }

  // Bytes thrown away while resynchronising.
  [[nodiscard]] std::size_t dropped_bytes() const { return dropped_; }
  // Bytes held for a frame that is not complete yet.
  [[nodiscard]] std::size_t buffered() const { return end_ - begin_; }
  // Whether the bytes held are the beginning of a frame that carries `counter` (its low byte, for a byte counter): as
  // much of the header as has come agrees (a valid length, the counter's bytes; a part of the length alone agrees
  // with any frame). The frame a sender whose sequence is at `counter` is in the middle of, rather than garbage.
  // False when nothing is held, and for framings without a counter.
  [[nodiscard]] bool holds_start_of_frame(std::uint16_t counter) const;

  // Gives up on what is buffered: drops bytes one at a time, still delivering any valid frame that starts behind
  // them, until nothing is left. For links that send whole frames at once: a partial frame that waits too long
  // (an inter-frame gap) was garbage that looked like a header.
  template <typename OnPacket>
  void flush_stale(OnPacket&& on_packet) {
    while (buffered() > 0) {
      consume(1);
      ++dropped_;
      deliver(on_packet);
    }
  }
  // Forgets a partial frame (the link was reset).
  void reset() { begin_ = end_ = 0; }

 private:
  struct Frame {
    std::size_t size = 0;
    std::size_t packet_size = 0;
    std::uint16_t counter = 0;
    explicit operator bool() const { return size != 0; }
  };

  // Hands every complete, valid frame buffered to `on_packet`.
  template <typename OnPacket>
  void deliver(OnPacket& on_packet) {
    while (const Frame frame = next_frame()) {
      on_packet(frame.counter,
                std::span<const std::uint8_t>{buffer_.data() + begin_ + framing_.header_size(), frame.packet_size});
      consume(frame.size);
    }
  }

  // The complete, valid frame at the start of what is buffered, dropping garbage before it; an empty Frame if more
  // bytes are needed first.
  Frame next_frame();
  // Frames are taken from the front by moving begin_; the bytes move down only when the buffer's end is reached.
  void consume(std::size_t count) {
    begin_ += count;
    if (begin_ == end_) begin_ = end_ = 0;
  }
  void compact();

  Framing framing_;
  std::span<std::uint8_t> buffer_;
  std::size_t max_packet_;
  std::size_t begin_ = 0;  // the first byte not taken yet
  std::size_t end_ = 0;    // one past the last byte received
  std::size_t dropped_ = 0;
};

}  // namespace duet::xcp
