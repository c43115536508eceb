#include "duet/link/tcp.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <utility>

namespace duet::link {
namespace {

std::string system_error(const std::string& what) { return what + ": " + std::strerror(errno); }

// getaddrinfo's answers, freed when they go.
class Addresses {
 public:
  static Result<Addresses> resolve(const HostPort& address, bool passive) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    hints.ai_flags = AI_NUMERICSERV | (passive ? AI_PASSIVE : 0);
    addrinfo* found = nullptr;
    const std::string port = std::to_string(address.port);
    if (const int error = ::getaddrinfo(address.host.c_str(), port.c_str(), &hints, &found); error != 0) {
      return Failure{"cannot resolve '" + address.host + "': " + ::gai_strerror(error)};
    }
    return Addresses{found};
  }
  Addresses(Addresses&& other) noexcept : list_(std::exchange(other.list_, nullptr)) {}
  Addresses& operator=(Addresses&&) = delete;
  Addresses(const Addresses&) = delete;
  Addresses& operator=(const Addresses&) = delete;
  ~Addresses() {
    if (list_ != nullptr) ::freeaddrinfo(list_);
  }
  [[nodiscard]] const addrinfo* first() const { return list_; }

 private:
  explicit Addresses(addrinfo* list) : list_(list) {}
  addrinfo* list_;
};

std::string numeric_address(const sockaddr* address, socklen_t size) {
  char host[NI_MAXHOST] = {};
  char port[NI_MAXSERV] = {};
  if (::getnameinfo(address, size, host, sizeof host, port, sizeof port, NI_NUMERICHOST | NI_NUMERICSERV) != 0) {
    return "an unknown address";
  }
  const std::string text{host};
  return (text.find(':') != std::string::npos ? "[" + text + "]" : text) + ":" + port;
}

void set_no_delay(int fd) {
  const int on = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
}

// connect(2) with a time limit: started non-blocking, finished when the socket becomes writable.
Status connect_within(int fd, const addrinfo& address, Timeout timeout) {
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
  if (::connect(fd, address.ai_addr, address.ai_addrlen) == 0) return done();
  if (errno != EINPROGRESS) return Failure{std::strerror(errno)};
  pollfd poll_fd{.fd = fd, .events = POLLOUT, .revents = 0};
  const int wait_ms = timeout == no_timeout ? -1 : static_cast<int>(timeout.count());
  int ready = 0;
  while ((ready = ::poll(&poll_fd, 1, wait_ms)) < 0 && errno == EINTR) {
  }
  if (ready == 0) return Failure{"no answer within " + std::to_string(timeout.count()) + " ms"};
  int error = 0;
  socklen_t size = sizeof error;
  ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &size);
  if (error != 0) return Failure{std::strerror(error)};
  return done();
}

}  // namespace

Result<HostPort> parse_host_port(std::string_view text) {
  const auto fail = [text](const std::string& why) {
    return Failure{"'" + std::string{text} + "' is not HOST:PORT (" + why + ")"};
  };
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos) return fail("no ':' before the port");
  std::string_view host = text.substr(0, colon);
  const std::string_view port = text.substr(colon + 1);
  if (host.starts_with('[') != host.ends_with(']') || (host.size() == 1 && host.starts_with('['))) {
    return fail("an IPv6 address goes in brackets: [::1]:5601");
  }
  if (host.starts_with('[')) host = host.substr(1, host.size() - 2);
  if (host.find(':') != std::string_view::npos && !text.starts_with('[')) {
    return fail("an IPv6 address goes in brackets: [::1]:5601");
  }
  unsigned value = 0;
  const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || error != std::errc{} || end != port.data() + port.size() || value > 65535) {
    return fail("the port must be a number from 0 to 65535");
  }
  return HostPort{host.empty() ? "127.0.0.1" : std::string{host}, static_cast<std::uint16_t>(value)};
}

std::string to_string(const HostPort& address) {
  const bool v6 = address.host.find(':') != std::string::npos;
  return (v6 ? "[" + address.host + "]" : address.host) + ":" + std::to_string(address.port);
}

Result<std::unique_ptr<FdStream>> connect_tcp(const HostPort& address, Timeout timeout) {
  auto addresses = Addresses::resolve(address, false);
  if (!addresses) return Failure{addresses.error()};
  std::string why;
  for (const addrinfo* candidate = addresses.value().first(); candidate != nullptr; candidate = candidate->ai_next) {
    const int fd = ::socket(candidate->ai_family, candidate->ai_socktype | SOCK_CLOEXEC, candidate->ai_protocol);
    if (fd < 0) {
      why = std::strerror(errno);
      continue;
    }
    if (const Status connected = connect_within(fd, *candidate, timeout); !connected) {
      why = connected.error();
      ::close(fd);
      continue;
    }
    set_no_delay(fd);
    return std::make_unique<FdStream>(fd, fd, timeout);
  }
  return Failure{"cannot connect to " + to_string(address) + ": " + why};
}

Result<TcpListener> TcpListener::open(const HostPort& address) {
  auto addresses = Addresses::resolve(address, true);
  if (!addresses) return Failure{addresses.error()};
  const addrinfo& chosen = *addresses.value().first();
  const int fd = ::socket(chosen.ai_family, chosen.ai_socktype | SOCK_CLOEXEC, chosen.ai_protocol);
  if (fd < 0) return Failure{system_error("socket")};
  const int on = 1;
  ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  if (::bind(fd, chosen.ai_addr, chosen.ai_addrlen) != 0 || ::listen(fd, 1) != 0) {
    const std::string message = system_error("cannot listen on " + to_string(address));
    ::close(fd);
    return Failure{message};
  }
  sockaddr_storage bound{};
  socklen_t size = sizeof bound;
  HostPort actual = address;
  if (::getsockname(fd, reinterpret_cast<sockaddr*>(&bound), &size) == 0) {
    actual.port = ntohs(bound.ss_family == AF_INET6 ? reinterpret_cast<const sockaddr_in6*>(&bound)->sin6_port
                                                    : reinterpret_cast<const sockaddr_in*>(&bound)->sin_port);
  }
  return TcpListener{fd, actual};
}

TcpListener::TcpListener(TcpListener&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), address_(std::move(other.address_)) {}

TcpListener& TcpListener::operator=(TcpListener&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    address_ = std::move(other.address_);
  }
  return *this;
}

TcpListener::~TcpListener() {
  if (fd_ >= 0) ::close(fd_);
}

Result<TcpListener::Accepted> TcpListener::accept(Timeout timeout, Timeout stream_timeout) {
  pollfd poll_fd{.fd = fd_, .events = POLLIN, .revents = 0};
  const int wait_ms = timeout == no_timeout ? -1 : static_cast<int>(timeout.count());
  for (;;) {
    const int ready = ::poll(&poll_fd, 1, wait_ms);
    if (ready == 0) return Failure{"no connection within " + std::to_string(timeout.count()) + " ms"};
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return Failure{system_error("poll")};
    sockaddr_storage peer{};
    socklen_t size = sizeof peer;
    const int fd = ::accept4(fd_, reinterpret_cast<sockaddr*>(&peer), &size, SOCK_CLOEXEC);
    if (fd < 0 && (errno == EINTR || errno == ECONNABORTED || errno == EAGAIN)) continue;
    if (fd < 0) return Failure{system_error("accept")};
    set_no_delay(fd);
    Accepted accepted;
    accepted.peer = numeric_address(reinterpret_cast<const sockaddr*>(&peer), size);
    accepted.stream = std::make_unique<FdStream>(fd, fd, stream_timeout);
    return accepted;
  }
}

}  // namespace duet::link
