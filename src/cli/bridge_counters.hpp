#pragma once
// The XCP traffic duet-bridge reports when it stops: its last words on standard error are its counters
// ("duet-bridge: stopped; channel open, master none; frames to master 12 (340 bytes), to slave 6 (60 bytes); DAQ
// frames dropped 0; garbage bytes 0; channel opened 1 times; masters served 1, refused 0; latency mean 80 us, max
// 140 us; application channel {...}", Relay::status in src/bridge/relay.cpp).

#include <cstdint>
#include <optional>
#include <string_view>

namespace duet::cli {

struct XcpTraffic {
  std::uint64_t frames_to_master = 0;
  std::uint64_t bytes_to_master = 0;
  std::uint64_t frames_to_slave = 0;
  std::uint64_t bytes_to_slave = 0;
  std::uint64_t daq_frames_dropped = 0;
  std::uint64_t masters_served = 0;
};

// The counters of the last "stopped" line in what the bridge printed; none when there is no such line or it does
// not read as expected.
[[nodiscard]] std::optional<XcpTraffic> parse_bridge_counters(std::string_view output);

}  // namespace duet::cli
