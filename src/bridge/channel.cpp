#include "channel.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>

namespace duet::bridge {

Result<ChannelAddress> parse_channel(std::string_view uri) {
  const auto fail = [&](std::string_view problem) {
    return Failure{"channel '" + std::string{uri} + "': " + std::string{problem} +
                   " (expected tty:/dev/ttyRPMSG0, unix:/path or tcp://host:port)"};
  };
  if (uri.starts_with("tty:") && uri.size() > 4) return ChannelAddress{ChannelKind::tty, std::string{uri.substr(4)}, 0};
  if (uri.starts_with("unix:") && uri.size() > 5)
    return ChannelAddress{ChannelKind::unix_socket, std::string{uri.substr(5)}, 0};
  if (uri.starts_with("tcp://")) {
    const std::string_view rest = uri.substr(6);
    const std::size_t colon = rest.rfind(':');
    unsigned port = 0;
    if (colon == std::string_view::npos || colon == 0) return fail("no host:port");
    const std::string_view digits = rest.substr(colon + 1);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), port);
    if (error != std::errc{} || end != digits.data() + digits.size() || port == 0 || port > 65535) {
      return fail("the port must be a number from 1 to 65535");
    }
    return ChannelAddress{ChannelKind::tcp, std::string{rest.substr(0, colon)}, port};
  }
  return fail("unknown kind");
}

Result<int> open_channel(const ChannelAddress& address) {
  const auto system_error = [&](const std::string& what) {
    return Failure{address.path + ": " + what + ": " + std::strerror(errno)};
  };
  if (address.kind == ChannelKind::tty) {
    const int descriptor = ::open(address.path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (descriptor < 0) return system_error("open");
    termios settings{};
    if (tcgetattr(descriptor, &settings) == 0) {  // a tty: bytes pass as they are
      cfmakeraw(&settings);
      tcsetattr(descriptor, TCSANOW, &settings);
    }
    return descriptor;
  }
  if (address.kind == ChannelKind::unix_socket) {
    const int descriptor = ::socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
    sockaddr_un socket_address{};
    socket_address.sun_family = AF_UNIX;
    if (address.path.size() >= sizeof(socket_address.sun_path)) {
      ::close(descriptor);
      return Failure{address.path + ": the path is too long for a unix socket"};
    }
    std::memcpy(socket_address.sun_path, address.path.c_str(), address.path.size() + 1);
    if (::connect(descriptor, reinterpret_cast<sockaddr*>(&socket_address), sizeof(socket_address)) != 0) {
      const Failure failure = system_error("connect");
      ::close(descriptor);
      return failure;
    }
    return descriptor;
  }
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const std::string port = std::to_string(address.port);
  if (const int error = getaddrinfo(address.path.c_str(), port.c_str(), &hints, &found); error != 0) {
    return Failure{address.path + ":" + port + ": " + gai_strerror(error)};
  }
  const int descriptor = ::socket(found->ai_family, SOCK_STREAM | SOCK_CLOEXEC, 0);
  const int connected = ::connect(descriptor, found->ai_addr, found->ai_addrlen);
  freeaddrinfo(found);
  if (connected != 0) {
    const Failure failure = system_error("connect");
    ::close(descriptor);
    return failure;
  }
  fcntl(descriptor, F_SETFL, fcntl(descriptor, F_GETFL) | O_NONBLOCK);
  return descriptor;
}

}  // namespace duet::bridge
