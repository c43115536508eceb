#pragma once
// What the commands that serve a page (duet monitor, duet studio) share: the address they listen on, refused beyond
// this machine unless --expose says so, and serving on a thread of its own until Ctrl-C.

#include <boost/asio/io_context.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "duet/link/tcp.hpp"
#include "stop_signals.hpp"

namespace duet::cli {

// The --listen address (already checked by host_port_validator), or none once `command` said on `err` why not.
[[nodiscard]] std::optional<link::HostPort> listen_address(const std::string& listen, bool expose,
                                                           std::string_view command, std::ostream& err);

// Runs `io` on a thread of its own until `stop` says SIGINT or SIGTERM came, then stops it and waits for the thread.
void serve_until_stopped(boost::asio::io_context& io, StopSignals& stop);

}  // namespace duet::cli
