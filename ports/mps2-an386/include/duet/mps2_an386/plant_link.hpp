#pragma once
// The firmware's end of the virtual-hardware link (docs/LINK.md) under QEMU: the model's hardware calls become
// WRITE and READ frames to a simulated plant in a host program, and each base tick a TICK, during which the plant's
// interrupts (INTERRUPT frames) run the model's interrupt tasks.
//
// The frames travel through two named pipes of the host that semihosting opens, reads and writes: QEMU's UART model
// moves one byte per turn of its main loop (a UART link ran the robot at a sixth of real time), while a semihosting
// call blocks the core until the host's read or write returns, which takes no emulated time. Frames that need no
// answer (WRITE) wait in a buffer until the link next waits for the plant, and one read takes whatever the plant has
// sent, so that a tick costs the host a pipe write and a read per round trip rather than one per frame: each write
// woke the plant's thread, which is what a real-time run spends its wall time on (docs/LINK.md, "Pacing").
//
// While it talks to the plant the link masks interrupts and counts its own cycles apart, and PlantLinkedPort's cycle
// count leaves them out: the firmware sees its plant as it would see registers, the instructions that encode and
// decode frames are not counted in the execution times the executive measures. The timers run on (the link's own
// instructions are a few hundred a tick): pausing and restarting them at every exchange, as the link did before, was
// two timers for QEMU to reschedule each time, a good part of a paced tick's wall time (docs/LINK.md, "Pacing"). A
// blocking semihosting call takes no emulated time under -icount, so how fast the plant answers (at once: lock-step; at
// the wall clock's pace: real time) is the plant's business; the firmware's run is the same either way.
//
// Freestanding. A failure (garbage, an ERROR from the plant, the pipe closed) is kept: from then on the calls do
// nothing, reads give zeros, and error() says what happened.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "duet/base/text_buffer.hpp"
#include "duet/link/frame.hpp"
#include "duet/link/frame_decoder.hpp"
#include "duet/mps2_an386/executive_port.hpp"

namespace duet::mps2_an386 {

class PlantLink {
 public:
  // Opens the pipes (paths NUL-terminated beyond their views; the plant creates them and opens its ends), then the
  // session: HELLO (lock-step, the model's base period) and the plant's HELLO_OK.
  bool connect(std::string_view to_plant, std::string_view from_plant, std::uint32_t base_period_ns);

  // The elements go in their own types (WRITE, READ and VALUES of bool, u8, u16, u32 or f32 elements): nothing on the
  // firmware's side converts to or from double, which the M4F's FPU does not have. The plant converts as the
  // interpreter does. Defined for the types hardware.hpp's calls move.
  template <typename Element>
  void write(std::string_view resource, std::span<const Element> values);
  template <typename Element>
  void read(std::string_view resource, std::span<Element> values);

  // Sends the pins written since the link last talked to the plant (duet/hardware/hardware.hpp's plant_pin_writes),
  // as when it next does: for when they fill their buffer.
  void send_pin_writes();

  // Moves the plant to base tick `tick` (its time is the plant's to compute: tick x the base period HELLO gave).
  // Each interrupt it raises on the way pends that interrupt's line (board.hpp's plant_interrupts) and lets it run,
  // with time running, before the plant goes on: the task must be more urgent than the caller (the base tick's
  // handler).
  void tick(std::uint64_t tick);

  // Ends the session.
  void bye();

  [[nodiscard]] bool ok() const { return error_.view().empty(); }

  // The cycles spent in the link so far, by all links (wrapping as the cycle counter does).
  [[nodiscard]] static std::uint32_t cycles_spent() { return cycles_spent_; }
  [[nodiscard]] std::string_view error() const { return error_.view(); }

 private:
  // The largest frame the plant sends to this firmware: VALUES of 255 u32 elements; a longer one is refused.
  static constexpr std::size_t max_received_payload = 1024;

  // Frames waiting to go out: a tick's WRITEs (some 11 for the robot, 30 bytes each) and the frame that waits.
  static constexpr std::size_t outgoing_capacity = 2048;

  class LinkSection;
  // Queues the pins written meanwhile, then a frame; they go out with the next flush().
  void send(std::span<const std::uint8_t> frame);
  void queue(std::span<const std::uint8_t> frame);
  void queue_pin_writes();
  void flush();
  // Flushes, then waits for the plant's next frame; false (and the session failed) on garbage, an ERROR or the
  // pipe's end.
  bool receive();
  // Reads what the plant has sent (at least a byte, waiting for it) into `incoming_`; false at the pipe's end.
  bool read_more();
  bool expect(link::FrameKind kind);
  bool raise(std::string_view name, LinkSection& section);
  void fail(std::string_view what, std::string_view detail = {});

  static inline std::uint32_t cycles_spent_ = 0;
  int to_plant_ = -1;
  int from_plant_ = -1;
  link::BasicFrameDecoder<max_received_payload> decoder_;
  std::uint8_t frame_[max_received_payload + link::header_size]{};  // where a frame is encoded
  std::uint8_t outgoing_[outgoing_capacity]{};
  std::size_t outgoing_size_ = 0;
  std::uint8_t incoming_[max_received_payload + link::header_size]{};
  std::size_t incoming_begin_ = 0;  // the bytes from here to incoming_end_ are not decoded yet
  std::size_t incoming_end_ = 0;
  TextBuffer<160> error_;
};

// The executive's port for an image with a plant link: its cycle count leaves out the cycles the link spent talking
// to the plant.
class PlantLinkedPort : public ExecutivePort {
 public:
  [[nodiscard]] static std::uint32_t cycles();
};

}  // namespace duet::mps2_an386
