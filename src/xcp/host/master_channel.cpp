#include "duet/xcp/host/master_channel.hpp"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <string>

namespace duet::xcp::host {
namespace {

constexpr std::size_t max_packet = 0xFFFF;
constexpr std::chrono::microseconds spin{200};

std::string system_error(const char* what) { return std::string{what} + ": " + std::strerror(errno); }

}  // namespace

Result<std::unique_ptr<MasterChannel>> MasterChannel::open(const Endpoint& endpoint,
                                                           std::chrono::milliseconds timeout) {
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = endpoint.protocol == Protocol::tcp ? SOCK_STREAM : SOCK_DGRAM;
  addrinfo* found = nullptr;
  const std::string port = std::to_string(endpoint.port);
  if (const int error = getaddrinfo(endpoint.host.c_str(), port.c_str(), &hints, &found); error != 0) {
    return Failure{to_string(endpoint) + ": " + gai_strerror(error)};
  }
  const int socket = ::socket(found->ai_family, found->ai_socktype | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (socket < 0) {
    freeaddrinfo(found);
    return Failure{system_error("socket")};
  }
  const int connected = ::connect(socket, found->ai_addr, found->ai_addrlen);
  freeaddrinfo(found);
  if (connected != 0 && errno != EINPROGRESS) {
    const std::string message = to_string(endpoint) + ": " + system_error("connect");
    ::close(socket);
    return Failure{message};
  }
  if (connected != 0) {  // TCP: wait for the handshake
    pollfd waiting{socket, POLLOUT, 0};
    int error = 0;
    socklen_t length = sizeof(error);
    if (::poll(&waiting, 1, static_cast<int>(timeout.count())) != 1 ||
        getsockopt(socket, SOL_SOCKET, SO_ERROR, &error, &length) != 0 || error != 0) {
      ::close(socket);
      return Failure{to_string(endpoint) + ": cannot connect" +
                     (error != 0 ? std::string{": "} + std::strerror(error) : "")};
    }
  }
  if (endpoint.protocol == Protocol::tcp) {
    const int on = 1;
    setsockopt(socket, IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));  // commands are small and want answers now
  }
  return std::unique_ptr<MasterChannel>{new MasterChannel{socket, endpoint.protocol}};
}

MasterChannel::MasterChannel(int socket, Protocol protocol)
    : socket_(socket),
      protocol_(protocol),
      decoder_buffer_(ethernet_framing.frame_size(max_packet)),
      decoder_(ethernet_framing, decoder_buffer_, max_packet) {}

MasterChannel::~MasterChannel() { ::close(socket_); }

Status MasterChannel::send(std::span<const std::uint8_t> packet) {
  std::vector<std::uint8_t> frame(ethernet_framing.frame_size(packet.size()));
  if (write_frame(ethernet_framing, frame, send_counter_++, packet) == 0) return Failure{"packet too long to send"};
  std::size_t sent = 0;
  while (sent < frame.size()) {
    const ssize_t written = ::send(socket_, frame.data() + sent, frame.size() - sent, MSG_NOSIGNAL);
    if (written < 0 && (errno == EAGAIN || errno == EINTR)) {
      pollfd waiting{socket_, POLLOUT, 0};
      ::poll(&waiting, 1, 100);
      continue;
    }
    if (written <= 0) return Failure{system_error("send")};
    sent += static_cast<std::size_t>(written);
  }
  return done();
}

void MasterChannel::take(std::span<const std::uint8_t> bytes) {
  bytes_received_ += bytes.size();
  decoder_.feed(bytes, [this](std::uint16_t counter, std::span<const std::uint8_t> packet) {
    if (expected_counter_ && counter != *expected_counter_) {
      counter_gaps_ += static_cast<std::uint16_t>(counter - *expected_counter_);
    }
    expected_counter_ = static_cast<std::uint16_t>(counter + 1);
    packets_.emplace_back(packet.begin(), packet.end());
  });
}

Result<std::optional<std::vector<std::uint8_t>>> MasterChannel::receive(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::vector<std::uint8_t>& buffer = receive_buffer_;
  // Answers on localhost come within tens of microseconds: ask again for a short while before sleeping in poll,
  // which would add the scheduler's wake-up time to every round trip.
  const auto spin_until =
      std::chrono::steady_clock::now() + std::min<std::chrono::steady_clock::duration>(spin, timeout);
  while (packets_.empty() && std::chrono::steady_clock::now() < spin_until) {
    const ssize_t received = ::recv(socket_, buffer.data(), buffer.size(), MSG_DONTWAIT);
    if (received > 0) {
      if (protocol_ == Protocol::udp) decoder_.reset();
      take(std::span{buffer}.first(static_cast<std::size_t>(received)));
    } else if (received == 0 && protocol_ == Protocol::tcp) {
      return Failure{"the slave closed the connection"};
    } else if (received < 0 && errno != EAGAIN && errno != EINTR) {
      return Failure{system_error("receive")};
    }
  }
  while (packets_.empty()) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    pollfd waiting{socket_, POLLIN, 0};
    const int ready = ::poll(&waiting, 1, left.count() > 0 ? static_cast<int>(left.count()) : 0);
    if (ready < 0 && errno != EINTR) return Failure{system_error("poll")};
    if (ready <= 0) {
      if (left.count() <= 0) return std::optional<std::vector<std::uint8_t>>{};
      continue;
    }
    const ssize_t received = ::recv(socket_, buffer.data(), buffer.size(), 0);
    if (received == 0 && protocol_ == Protocol::tcp) return Failure{"the slave closed the connection"};
    if (received < 0) {
      if (errno == EAGAIN || errno == EINTR) continue;
      return Failure{system_error("receive")};
    }
    if (protocol_ == Protocol::udp) decoder_.reset();  // a datagram holds whole frames only
    take(std::span{buffer}.first(static_cast<std::size_t>(received)));
  }
  std::vector<std::uint8_t> packet = std::move(packets_.front());
  packets_.pop_front();
  return std::optional<std::vector<std::uint8_t>>{std::move(packet)};
}

}  // namespace duet::xcp::host
