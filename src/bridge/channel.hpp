#pragma once
// The bridge's link to the real-time core's XCP channel, opened from a URI:
//   tty:/dev/ttyRPMSG0   a tty or pty (raw mode: no echo, no line editing, no output processing)
//   unix:/path/socket    a unix stream socket (connected)
//   tcp://host:port      a TCP connection (e.g. QEMU's -serial tcp:...)
// Every descriptor is non-blocking and close-on-exec.

#include <string>
#include <string_view>

#include "duet/support/result.hpp"

namespace duet::bridge {

enum class ChannelKind { tty, unix_socket, tcp };

struct ChannelAddress {
  ChannelKind kind = ChannelKind::tty;
  std::string path;  // tty and unix: the path; tcp: the host
  unsigned port = 0;
};

Result<ChannelAddress> parse_channel(std::string_view uri);

// Opens the channel; the descriptor is the caller's to close.
Result<int> open_channel(const ChannelAddress& address);

}  // namespace duet::bridge
