#pragma once
// The XCP relay: frames between the real-time core's channel and one master on TCP or UDP, in one epoll loop.
//
// - Frame-aware both ways (XCP-on-TCP framing, LEN/CTR): garbage is skipped (counted), partial frames wait, frames
//   pass unchanged.
// - One master at a time: a second connection is closed at once, and logged; on UDP, the master is the peer of the
//   first datagram while there is none, datagrams from others are dropped (logged once), and it is gone after its
//   DISCONNECT has been answered (at once if the slave will not answer it) or after 30 s of silence.
// - The session is watched (session_tracker.hpp): a master that goes away (cleanly or not) while the slave's session
//   is open is disconnected on its behalf, so that DAQ stops; the answers owed to it and to that DISCONNECT go to
//   nobody, and the next master's commands wait until they have come (or given up after a while), so that no answer
//   of theirs reaches the wrong master.
// - A command that cannot reach the slave (no channel, or too much waiting for it) is answered by the relay with
//   ERR_CMD_BUSY, which tells a master to try again; every frame lost on the way is counted.
// - The channel going away (closed tty, firmware restarted) is retried with back-off; the listener stays open.
// - Towards the master the queue is bounded: past the limit DAQ frames are dropped (counted), responses never. The
//   channel is read whenever it has bytes; writes to it go in chunks of at most 496 bytes (an RPMsg payload) and are
//   retried with back-off when the channel says EAGAIN or ENOMEM.
// - LEN/CTR framing has no checksum, so a garbage byte can look like a header and hold the decoder up: a partial
//   frame still waiting after a quiet gap (20 ms) is dropped byte by byte and the frames behind it are found. But not
//   on the channel when what has come of the partial frame's header agrees with the counter that follows the slave's
//   last frame: that is the slave's next frame on its way, which a link may pause in the middle of, header included,
//   for longer than the gap (QEMU's UART writes a byte at a time from a thread the host may deschedule for tens of
//   milliseconds). Dropping it would lose it, and its remaining bytes, read as a header, could claim up to 64 KB and
//   swallow the frames behind them, answers too, until the next quiet gap.

#include <netinet/in.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "channel.hpp"
#include "duet/support/result.hpp"
#include "duet/xcp/framing.hpp"
#include "session_tracker.hpp"

namespace duet::bridge {

struct RelayOptions {
  ChannelAddress channel;
  std::string channel_uri;  // as given, for messages
  std::string listen_address = "127.0.0.1";
  std::uint16_t listen_port = 5555;  // 0: any free port
  std::size_t master_queue_limit = 1U << 20;
  // Commands waiting to be written to the channel or held back (masters wait for answers: little ever waits).
  std::size_t slave_queue_limit = std::size_t{64} * 1024;
  // The kernel's send buffer towards the master: with the queue, all a slow master can hold up (0: the kernel's).
  int master_send_buffer = 256 * 1024;
  std::size_t channel_chunk = 496;
  // A partial frame that waits this long without a byte is garbage (unless it is the slave's next frame, above).
  std::chrono::milliseconds quiet_gap{20};
  // How long the answers owed to a master that left (and to the relay's DISCONNECT) may take (SessionTracker).
  std::chrono::milliseconds owed_answer_patience = SessionTracker::default_owed_answer_patience;
  bool verbose = false;
};

struct RelayCounters {
  std::uint64_t frames_to_master = 0;
  std::uint64_t frames_to_slave = 0;
  std::uint64_t bytes_to_master = 0;
  std::uint64_t bytes_to_slave = 0;
  std::uint64_t daq_frames_dropped = 0;
  // Answers, events and service requests a UDP master could not be sent (too long for a datagram, or refused).
  std::uint64_t answers_dropped = 0;
  // Frames from the slave for a master that is gone: DAQ after it left, answers owed to it or to the relay.
  std::uint64_t frames_without_master = 0;
  std::uint64_t commands_refused = 0;     // answered ERR_CMD_BUSY by the relay: no channel, or too many waiting
  std::uint64_t commands_unanswered = 0;  // waited for an answer that never came (SessionTracker)
  std::uint64_t garbage_bytes = 0;        // bytes that were no whole frame
  std::uint64_t channel_opens = 0;
  std::uint64_t masters_served = 0;
  std::uint64_t masters_refused = 0;
  std::uint64_t responses = 0;  // answers paired with their command
  double latency_mean_us = 0;   // command forwarded -> its answer back
  double latency_max_us = 0;
};

// Bytes waiting to be sent: appended at the back, sent from the front, contiguous for send().
class ByteQueue {
 public:
  void append(std::span<const std::uint8_t> bytes) { bytes_.insert(bytes_.end(), bytes.begin(), bytes.end()); }
  [[nodiscard]] std::span<const std::uint8_t> front() const { return std::span{bytes_}.subspan(head_); }
  [[nodiscard]] std::size_t size() const { return bytes_.size() - head_; }
  [[nodiscard]] bool empty() const { return size() == 0; }
  void consume(std::size_t count) {
    head_ += count;
    if (head_ == bytes_.size()) {
      bytes_.clear();
      head_ = 0;
    } else if (head_ > bytes_.size() / 2) {  // keep the storage from growing without bound
      bytes_.erase(bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(head_));
      head_ = 0;
    }
  }
  void clear() {
    bytes_.clear();
    head_ = 0;
  }

 private:
  std::vector<std::uint8_t> bytes_;
  std::size_t head_ = 0;
};

class Relay {
 public:
  explicit Relay(RelayOptions options);
  ~Relay();
  Relay(const Relay&) = delete;
  Relay& operator=(const Relay&) = delete;

  // Binds the listener and tries the channel (a channel that is not there yet is retried).
  Status start();
  // Serves until stop() (from any thread) or, with `handle_signals`, SIGINT/SIGTERM; SIGUSR1 logs the counters
  // (and `more_status()`, another service's).
  void run(bool handle_signals = false, const std::function<std::string()>& more_status = {});
  void stop();

  [[nodiscard]] std::uint16_t port() const { return port_; }
  [[nodiscard]] RelayCounters counters() const;
  [[nodiscard]] std::string status() const;
  [[nodiscard]] bool channel_open() const { return channel_open_.load(); }
  [[nodiscard]] bool master_connected() const { return master_connected_.load(); }

 private:
  void log(const std::string& line) const;
  void open_channel_now();
  void close_channel(const std::string& reason);
  void accept_master();
  void close_master(const std::string& reason);
  void forget_udp_master(const std::string& reason);
  void master_gone(const std::string& reason);
  void read_udp();
  void send_to_udp_master(std::uint16_t counter, std::span<const std::uint8_t> packet, bool daq);
  [[nodiscard]] bool has_master() const { return master_ >= 0 || udp_master_.has_value(); }
  void read_channel();
  void read_master();
  void flush_master();
  void flush_channel();
  void arm_retry(std::chrono::milliseconds delay);
  void update_interest();
  void enqueue_to_slave(std::uint16_t counter, std::span<const std::uint8_t> packet);
  void forward_to_master(std::uint16_t counter, std::span<const std::uint8_t> packet);
  void deliver_to_master(std::uint16_t counter, std::span<const std::uint8_t> packet);
  void forward_to_slave(std::uint16_t counter, std::span<const std::uint8_t> packet);
  void send_command(std::uint16_t counter, std::span<const std::uint8_t> packet);
  void refuse_command(std::span<const std::uint8_t> packet);
  void release_held_commands();
  // A partial frame whose rest will never come (its link ended, or its datagram did): its bytes were garbage.
  void discard_partial_frame(xcp::FrameDecoder& decoder);
  // A partial frame that waits longer than a gap was garbage, unless it is the slave's next frame (see above).
  void flush_stale_frames();

  RelayOptions options_;
  int epoll_ = -1;
  int listener_ = -1;
  int wake_ = -1;
  int retry_timer_ = -1;
  int channel_ = -1;
  int master_ = -1;
  int udp_ = -1;
  // A master on UDP is the peer of its datagrams: the first that sends while there is no master.
  std::optional<sockaddr_in> udp_master_;
  std::optional<sockaddr_in> last_refused_;  // logged once, not for every datagram
  std::chrono::steady_clock::time_point udp_master_heard_{};
  bool udp_master_leaving_ = false;                         // it sent DISCONNECT, which the slave will answer
  static constexpr std::size_t max_datagram_packet = 1468;  // an Ethernet frame's UDP payload less LEN/CTR
  bool channel_watched_for_output_ = false;
  bool master_watched_for_output_ = false;
  std::uint16_t port_ = 0;
  std::atomic<bool> running_{false};
  std::atomic<bool> channel_open_{false};
  std::atomic<bool> master_connected_{false};
  std::chrono::milliseconds retry_delay_{100};
  // When each decoder last made progress while holding a partial frame (see flush_stale_frames()).
  std::chrono::steady_clock::time_point channel_stalled_since_{};
  std::chrono::steady_clock::time_point master_stalled_since_{};
  // The counter of the frame the slave sends next (its last frame's + 1); none until a frame came on this channel.
  std::optional<std::uint16_t> slave_next_counter_;

  std::vector<std::uint8_t> read_buffer_ = std::vector<std::uint8_t>(65536);  // allocated once: reads are frequent
  std::vector<std::uint8_t> channel_buffer_;
  std::vector<std::uint8_t> master_buffer_;
  xcp::FrameDecoder from_channel_;
  xcp::FrameDecoder from_master_;
  ByteQueue to_master_;
  ByteQueue to_channel_;
  SessionTracker session_;
  // The master's commands held back while answers are owed to nobody (see SessionTracker), oldest first.
  struct HeldCommand {
    std::uint16_t counter = 0;
    std::vector<std::uint8_t> packet;
  };
  std::deque<HeldCommand> held_commands_;
  std::size_t held_bytes_ = 0;
  std::uint16_t next_counter_to_master_ = 0;  // for the relay's own answers, after the slave's last

  mutable std::atomic<std::uint64_t> frames_to_master_{0}, frames_to_slave_{0}, bytes_to_master_{0}, bytes_to_slave_{0},
      daq_frames_dropped_{0}, answers_dropped_{0}, frames_without_master_{0}, commands_refused_{0},
      commands_abandoned_{0}, partial_frame_bytes_{0}, channel_opens_{0}, masters_served_{0}, masters_refused_{0};
};

}  // namespace duet::bridge
