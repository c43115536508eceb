#pragma once
// For tests: a byte protocol (receive, transmit) that records what it received and frames what the test queued, a
// few bytes per frame as a real protocol frames packets, only whole frames into each message.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

namespace duet::rpmsg::testing {

struct RecordingProtocol {
  std::vector<std::uint8_t> received;
  std::deque<std::uint8_t> queued;
  std::size_t frame_size = 100;

  void receive(std::span<const std::uint8_t> bytes) { received.insert(received.end(), bytes.begin(), bytes.end()); }
  std::size_t transmit(std::span<std::uint8_t> out) {
    std::size_t written = 0;
    while (!queued.empty() && written + std::min(frame_size, queued.size()) <= out.size()) {
      const std::size_t frame = std::min(frame_size, queued.size());
      std::copy_n(queued.begin(), frame, out.begin() + static_cast<std::ptrdiff_t>(written));
      queued.erase(queued.begin(), queued.begin() + static_cast<std::ptrdiff_t>(frame));
      written += frame;
    }
    return written;
  }
};

}  // namespace duet::rpmsg::testing
