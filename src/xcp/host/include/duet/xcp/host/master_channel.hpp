#pragma once
// The master's end of XCP on Ethernet: a TCP connection or a UDP socket to one slave, LEN/CTR framing, and the
// packets that arrived but nobody has taken yet.

#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "duet/support/result.hpp"
#include "duet/xcp/framing.hpp"
#include "duet/xcp/host/endpoint.hpp"

namespace duet::xcp::host {

class MasterChannel {
 public:
  static Result<std::unique_ptr<MasterChannel>> open(const Endpoint& endpoint, std::chrono::milliseconds timeout);
  ~MasterChannel();
  MasterChannel(const MasterChannel&) = delete;
  MasterChannel& operator=(const MasterChannel&) = delete;

  Status send(std::span<const std::uint8_t> packet);
  // The next packet from the slave, waiting at most `timeout`; nothing if none came in time.
  Result<std::optional<std::vector<std::uint8_t>>> receive(std::chrono::milliseconds timeout);

  // Counter values missing from the slave's CTR sequence: packets the link or the slave lost.
  [[nodiscard]] std::uint64_t counter_gaps() const { return counter_gaps_; }
  // The next packet starts the CTR sequence afresh: after ERR_CMD_BUSY, which a bridge in front of the slave may
  // have said with a counter of its own, the slave's sequence takes over.
  void restart_counter() { expected_counter_.reset(); }
  [[nodiscard]] std::uint64_t bytes_received() const { return bytes_received_; }

 private:
  MasterChannel(int socket, Protocol protocol);
  void take(std::span<const std::uint8_t> bytes);

  int socket_;
  Protocol protocol_;
  std::uint16_t send_counter_ = 0;
  std::optional<std::uint16_t> expected_counter_;
  std::uint64_t counter_gaps_ = 0;
  std::uint64_t bytes_received_ = 0;
  std::vector<std::uint8_t> decoder_buffer_;
  std::vector<std::uint8_t> receive_buffer_ = std::vector<std::uint8_t>(65536);  // allocated once: reads are frequent
  FrameDecoder decoder_;
  std::deque<std::vector<std::uint8_t>> packets_;
};

}  // namespace duet::xcp::host
