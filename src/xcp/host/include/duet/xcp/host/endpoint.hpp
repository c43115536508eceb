#pragma once
// Where an XCP slave is reached: "tcp://host:port" or "udp://host:port".

#include <cstdint>
#include <string>
#include <string_view>

#include "duet/support/result.hpp"

namespace duet::xcp::host {

enum class Protocol : std::uint8_t { tcp, udp };

struct Endpoint {
  Protocol protocol = Protocol::tcp;
  std::string host = "127.0.0.1";
  std::uint16_t port = 5555;  // the port common XCP tools use
  bool operator==(const Endpoint&) const = default;
};

// Parses "tcp://host:port" or "udp://host:port"; the message of a failure quotes the text and says what is wrong.
Result<Endpoint> parse_endpoint(std::string_view text);

std::string to_string(const Endpoint& endpoint);

}  // namespace duet::xcp::host
