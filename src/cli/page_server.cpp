#include "page_server.hpp"

#include <poll.h>

#include <thread>

namespace duet::cli {

std::optional<link::HostPort> listen_address(const std::string& listen, bool expose, std::string_view command,
                                             std::ostream& err) {
  auto address = link::parse_host_port(listen).value();  // checked by the validator
  if (address.host != "127.0.0.1" && !expose) {
    err << command << ": --listen " << listen << " would reach beyond this machine: add --expose to mean it\n";
    return std::nullopt;
  }
  return address;
}

void serve_until_stopped(boost::asio::io_context& io, StopSignals& stop) {
  std::thread serving{[&io] { io.run(); }};
  pollfd signal_fd{stop.fd(), POLLIN, 0};
  while (!stop.received()) ::poll(&signal_fd, 1, -1);
  io.stop();
  serving.join();
}

}  // namespace duet::cli
