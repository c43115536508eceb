#include "duet/xcp/host/endpoint.hpp"

#include <charconv>

namespace duet::xcp::host {

Result<Endpoint> parse_endpoint(std::string_view text) {
  const auto fail = [&](std::string_view problem) {
    return Failure{"'" + std::string{text} + "': " + std::string{problem} +
                   " (expected tcp://host:port or udp://host:port)"};
  };
  Endpoint endpoint;
  std::string_view rest = text;
  if (rest.starts_with("tcp://")) {
    endpoint.protocol = Protocol::tcp;
  } else if (rest.starts_with("udp://")) {
    endpoint.protocol = Protocol::udp;
  } else {
    return fail("unknown scheme");
  }
  rest.remove_prefix(6);
  const std::size_t colon = rest.rfind(':');
  if (colon == std::string_view::npos || colon == 0) return fail("no host:port");
  endpoint.host = std::string{rest.substr(0, colon)};
  const std::string_view port = rest.substr(colon + 1);
  unsigned value = 0;
  const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (error != std::errc{} || end != port.data() + port.size() || value == 0 || value > 65535) {
    return fail("the port must be a number from 1 to 65535");
  }
  endpoint.port = static_cast<std::uint16_t>(value);
  return endpoint;
}

std::string to_string(const Endpoint& endpoint) {
  return std::string{endpoint.protocol == Protocol::tcp ? "tcp://" : "udp://"} + endpoint.host + ":" +
         std::to_string(endpoint.port);
}

}  // namespace duet::xcp::host
