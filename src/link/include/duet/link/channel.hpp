#pragma once
// One end of the link on the PC: frames out and in over a Stream. Frames sent are gathered and go out together
// just before the channel waits for an answer (or with flush()), so that a tick's writes cost no system call each;
// the order of frames is never changed. Failures name the peer ("the plant", "the firmware") and what was awaited.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "duet/link/frame.hpp"
#include "duet/link/frame_decoder.hpp"
#include "duet/link/stream.hpp"
#include "duet/support/result.hpp"

namespace duet::link {

// The plant's time at a tick, as a double: tick x base period, with the arithmetic of duet sim's robot (sil_run.cpp)
// and of the firmware before version 2 of the protocol, so that a run through the link is the run in one process bit
// for bit (tick 9 at 1 ms is 0.009000000000000001, which 9,000,000 ns would bring back as 0.009).
[[nodiscard]] inline double tick_time_s(std::uint64_t tick, std::uint32_t base_period_ns) {
  return static_cast<double>(tick) * (base_period_ns * 1e-9);
}

struct ReceivedFrame {
  FrameKind kind;
  std::span<const std::uint8_t> payload;  // valid until the channel's next receive()
};

// Not thread-safe; every call may block for the stream's timeout.
class Channel {
 public:
  // `stream` must outlive the channel. `peer` names the other end in messages: "the plant".
  Channel(Stream& stream, std::string peer);

  Status send_hello(const Hello& hello);
  Status send_hello_ok(const HelloOk& hello_ok);
  Status send_write(std::string_view resource, std::span<const double> values);
  Status send_read(std::string_view resource, ElementType type, std::size_t count);
  // For each element type of the protocol (bool, u8, u16, u32, float, double). Precondition: they fit a frame (a READ
  // asks for at most max_read_count).
  template <typename T>
  Status send_values(std::span<const T> values);
  Status send_tick(std::uint64_t tick);
  Status send_interrupt(std::string_view name);
  Status send_empty(FrameKind kind);  // INTERRUPT_DONE, TICK_DONE, BYE
  // Sends what is gathered.
  Status flush();

  // Flushes, then waits for the next frame: nothing when the peer closed the link between frames. `awaiting` says
  // what the caller waits for ("TICK_DONE"), for messages. A frame that the decoder refuses, a stream that ends in
  // the middle of a frame, a timeout and an error are failures; the peer is told with an ERROR frame where that
  // still makes sense.
  Result<std::optional<ReceivedFrame>> receive(std::string_view awaiting);

  // Tells the peer with an ERROR frame (best effort: the link may be broken already) and returns the failure.
  Failure fail(const std::string& message);
  // A failure about the peer: "<peer> <what>".
  [[nodiscard]] Failure peer_failure(const std::string& what) const;
  [[nodiscard]] const std::string& peer() const { return peer_; }

  // Frames counted since the channel was made.
  [[nodiscard]] std::uint64_t frames_sent() const { return frames_sent_; }
  [[nodiscard]] std::uint64_t frames_received() const { return frames_received_; }

 private:
  // Encodes a frame with `encode(buffer)` at the end of what is gathered, flushing first if it does not fit there.
  template <typename Encode>
  Status queue(FrameKind kind, Encode&& encode);
  // What is wrong, for the frame the decoder refused and for a stream that ended inside a frame.
  [[nodiscard]] std::string bad_frame() const;
  [[nodiscard]] std::string cut_frame() const;

  Stream& stream_;
  std::string peer_;
  std::array<std::uint8_t, 4 * max_frame> out_{};
  std::size_t queued_ = 0;
  std::array<std::uint8_t, max_frame> in_{};
  std::size_t in_begin_ = 0;
  std::size_t in_end_ = 0;
  FrameDecoder decoder_;
  std::uint64_t frames_sent_ = 0;
  std::uint64_t frames_received_ = 0;
};

}  // namespace duet::link
