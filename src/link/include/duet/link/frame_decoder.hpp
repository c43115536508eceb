#pragma once
// Finds the link's frames in a byte stream, whatever pieces the bytes arrive in: one at a time from a UART's
// interrupt, or a socket's reads of any size. The header is checked as soon as its bytes are there (an unknown kind
// at its first byte, a length this kind never has or one over the buffer at its third), so garbage is refused at
// once instead of being waited for. The link is a conversation, not a broadcast: after an error the decoder does not
// look for the next frame (a peer that sent garbage is not to be trusted), it stays in error until reset().
//
// Freestanding and header-only; the payload buffer is a member (Capacity bytes). Not interrupt-safe: one context
// feeds a decoder.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "duet/link/frame.hpp"

namespace duet::link {

enum class DecodeStatus : std::uint8_t {
  need_more,  // the frame is not complete yet
  frame,      // a frame is complete: kind() and payload(), until more bytes are fed
  error,      // error() says what; nothing more is taken until reset()
};

template <std::size_t Capacity = max_payload>
class BasicFrameDecoder {
  static_assert(Capacity >= 8 && Capacity <= max_payload, "a decoder holds at least a TICK, at most max_payload");

 public:
  // Takes one byte.
  constexpr DecodeStatus push(std::uint8_t byte) {
    const std::uint8_t one[1] = {byte};
    return feed(one).status;
  }

  struct Fed {
    std::size_t used = 0;  // bytes taken from the front of what was fed
    DecodeStatus status = DecodeStatus::need_more;
  };
  // Takes bytes up to the end of one frame, or up to an error: feed the rest (bytes.subspan(used)) after handling
  // the frame.
  constexpr Fed feed(std::span<const std::uint8_t> bytes) {
    if (error_ != FrameError::none) return {0, DecodeStatus::error};
    if (bytes.empty()) return {0, complete_ ? DecodeStatus::frame : DecodeStatus::need_more};
    if (complete_) start_frame();
    std::size_t used = 0;
    while (used < bytes.size()) {
      if (header_filled_ < header_size) {
        header_[header_filled_++] = bytes[used++];
        if (const FrameError error = check_header(); error != FrameError::none) {
          error_ = error;
          return {used, DecodeStatus::error};
        }
        if (header_filled_ == header_size && expected_ == 0) break;
        continue;
      }
      const std::size_t wanted = expected_ - filled_;
      const std::size_t taken = bytes.size() - used < wanted ? bytes.size() - used : wanted;
      for (std::size_t k = 0; k < taken; ++k) payload_[filled_ + k] = bytes[used + k];
      filled_ += taken;
      used += taken;
      if (filled_ == expected_) break;
    }
    complete_ = header_filled_ == header_size && filled_ == expected_;
    return {used, complete_ ? DecodeStatus::frame : DecodeStatus::need_more};
  }

  // The complete frame's kind and payload. Precondition: the last status was DecodeStatus::frame.
  [[nodiscard]] constexpr FrameKind kind() const { return static_cast<FrameKind>(header_[0]); }
  [[nodiscard]] constexpr std::span<const std::uint8_t> payload() const {
    return std::span<const std::uint8_t>{payload_}.first(filled_);
  }
  [[nodiscard]] constexpr FrameError error() const { return error_; }
  // Bytes of a frame under way (0 between frames, and once a frame is complete): a stream that ends with this above
  // 0 was cut in the middle of a frame.
  [[nodiscard]] constexpr std::size_t partial() const { return complete_ ? 0 : header_filled_ + filled_; }
  // The kind byte of the frame under way. Precondition: partial() > 0.
  [[nodiscard]] constexpr std::uint8_t partial_kind() const { return header_[0]; }
  // The payload length the frame under way (or refused) announced, once its header is complete (0 before).
  [[nodiscard]] constexpr std::size_t announced() const {
    return header_filled_ < header_size ? 0 : header_[1] | static_cast<std::size_t>(header_[2]) << 8U;
  }

  // Forgets everything: a partial frame, a complete one, an error.
  constexpr void reset() {
    start_frame();
    error_ = FrameError::none;
  }

 private:
  constexpr void start_frame() {
    header_filled_ = 0;
    filled_ = 0;
    expected_ = 0;
    complete_ = false;
  }

  constexpr FrameError check_header() {
    if (header_filled_ == 1) return is_frame_kind(header_[0]) ? FrameError::none : FrameError::unknown_kind;
    if (header_filled_ < header_size) return FrameError::none;
    const std::size_t length = announced();
    const FrameKind frame_kind = kind();
    if (length > Capacity) return FrameError::payload_too_long;
    const int fixed = fixed_payload(frame_kind);
    if (fixed >= 0 ? length != static_cast<std::size_t>(fixed) : length < min_payload(frame_kind)) {
      return FrameError::wrong_length;
    }
    expected_ = length;
    return FrameError::none;
  }

  std::array<std::uint8_t, header_size> header_{};
  std::array<std::uint8_t, Capacity> payload_{};
  std::size_t header_filled_ = 0;
  std::size_t filled_ = 0;
  std::size_t expected_ = 0;
  bool complete_ = false;
  FrameError error_ = FrameError::none;
};

using FrameDecoder = BasicFrameDecoder<>;

}  // namespace duet::link
