#include "duet/xcp/host/slave_server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

namespace duet::xcp::host {
namespace {

constexpr std::size_t max_packet = 0xFFFF;
constexpr std::size_t udp_datagram = 1400;  // stays below the usual MTU
constexpr int poll_milliseconds = 1;

}  // namespace

SlaveServer::SlaveServer(Slave& slave, TransmitQueue& queue, Exclusive exclusive)
    : slave_(slave),
      queue_(queue),
      exclusive_(std::move(exclusive)),
      decoder_buffer_(ethernet_framing.frame_size(max_packet)),
      decoder_(ethernet_framing, decoder_buffer_, max_packet) {}

SlaveServer::~SlaveServer() { stop(); }

Status SlaveServer::start(const Options& options) {
  protocol_ = options.protocol;
  pad_packets_ = options.pad_packets;
  listener_ = ::socket(AF_INET, (protocol_ == Protocol::tcp ? SOCK_STREAM : SOCK_DGRAM) | SOCK_CLOEXEC, 0);
  if (listener_ < 0) return Failure{std::string{"socket: "} + std::strerror(errno)};
  const int on = 1;
  setsockopt(listener_, SOL_SOCKET, SO_REUSEADDR, &on, sizeof(on));
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(options.port);
  if (inet_pton(AF_INET, options.address.c_str(), &address.sin_addr) != 1) {
    return Failure{"'" + options.address + "' is not an IPv4 address"};
  }
  if (::bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0 ||
      (protocol_ == Protocol::tcp && ::listen(listener_, 2) != 0)) {
    return Failure{options.address + ":" + std::to_string(options.port) + ": " + std::strerror(errno)};
  }
  socklen_t length = sizeof(address);
  getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length);
  port_ = ntohs(address.sin_port);
  wake_ = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  running_ = true;
  thread_ = std::thread{[this] { serve(); }};
  return done();
}

void SlaveServer::stop() {
  if (!running_.exchange(false)) return;
  notify();
  thread_.join();
  drop_master();
  for (int* descriptor : {&listener_, &wake_}) {
    if (*descriptor >= 0) ::close(*descriptor);
    *descriptor = -1;
  }
}

void SlaveServer::notify() const {
  if (wake_ < 0) return;
  const std::uint64_t one = 1;
  [[maybe_unused]] const ssize_t written = ::write(wake_, &one, sizeof(one));
}

// The master went away, cleanly or not: end its session on its behalf, so that DAQ stops.
void SlaveServer::drop_master() {
  if (protocol_ == Protocol::tcp && master_ >= 0) {
    ::close(master_);
    master_ = -1;
  }
  udp_peer_.clear();
  decoder_.reset();
  const std::array<std::uint8_t, 1> disconnect{static_cast<std::uint8_t>(Command::disconnect)};
  const auto end_session = [&] { (void)slave_.handle(disconnect); };
  exclusive_ ? exclusive_(end_session) : end_session();
  while (queue_.pop(packet_) != 0) {
  }
}

void SlaveServer::send_packet(std::span<const std::uint8_t> packet) {
  if (pad_packets_ && packet.size() % 4 != 0) {
    padded_.assign(packet.begin(), packet.end());
    padded_.resize((packet.size() + 3) / 4 * 4, 0);
    packet = padded_;
  }
  const std::size_t frame_size = ethernet_framing.frame_size(packet.size());
  if (protocol_ == Protocol::udp && outgoing_.size() + frame_size > udp_datagram) flush();
  const std::size_t at = outgoing_.size();
  outgoing_.resize(at + frame_size);
  write_frame(ethernet_framing, std::span{outgoing_}.subspan(at), counter_++, packet);
}

void SlaveServer::flush() {
  if (outgoing_.empty()) return;
  if (protocol_ == Protocol::udp) {
    if (!udp_peer_.empty()) {
      ::sendto(listener_, outgoing_.data(), outgoing_.size(), 0, reinterpret_cast<const sockaddr*>(udp_peer_.data()),
               static_cast<socklen_t>(udp_peer_.size()));
    }
  } else if (master_ >= 0) {
    std::size_t sent = 0;
    while (sent < outgoing_.size()) {  // a slow master slows the server; the transmit queue absorbs it
      const ssize_t written = ::send(master_, outgoing_.data() + sent, outgoing_.size() - sent, MSG_NOSIGNAL);
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) {
        drop_master();
        break;
      }
      sent += static_cast<std::size_t>(written);
    }
  }
  outgoing_.clear();
}

void SlaveServer::handle_bytes(std::span<const std::uint8_t> bytes) {
  decoder_.feed(bytes, [this](std::uint16_t, std::span<const std::uint8_t> packet) {
    std::span<const std::uint8_t> response;
    const auto handle = [&] { response = slave_.handle(packet); };
    exclusive_ ? exclusive_(handle) : handle();
    if (!response.empty()) send_packet(response);
  });
  flush();
}

void SlaveServer::drain_queue() {
  while (const std::size_t size = queue_.pop(packet_)) send_packet(std::span{packet_}.first(size));
  flush();
}

void SlaveServer::serve() {
  std::array<std::uint8_t, 65536> buffer{};
  while (running_) {
    std::array<pollfd, 3> watched{pollfd{listener_, POLLIN, 0}, pollfd{wake_, POLLIN, 0}, pollfd{master_, POLLIN, 0}};
    const nfds_t count = master_ >= 0 ? 3 : 2;
    if (::poll(watched.data(), count, poll_milliseconds) < 0 && errno != EINTR) break;
    if ((watched[1].revents & POLLIN) != 0) {
      std::uint64_t ignored = 0;
      [[maybe_unused]] const ssize_t read = ::read(wake_, &ignored, sizeof(ignored));
    }
    // The master's bytes first: a master that left and another that came in the same wait are served one after the
    // other, not refused as a second master.
    if (master_ >= 0 && (watched[2].revents & (POLLIN | POLLHUP | POLLERR)) != 0) {
      const ssize_t received = ::recv(master_, buffer.data(), buffer.size(), 0);
      if (received <= 0) {
        drop_master();
      } else {
        handle_bytes(std::span{buffer}.first(static_cast<std::size_t>(received)));
      }
    }
    if ((watched[0].revents & POLLIN) != 0) {
      if (protocol_ == Protocol::tcp) {
        const int accepted = ::accept4(listener_, nullptr, nullptr, SOCK_CLOEXEC);
        if (accepted >= 0 && master_ >= 0) {  // XCP has one master: refuse the second
          ::close(accepted);
          ++refused_masters_;
        } else if (accepted >= 0) {
          master_ = accepted;
          const int on = 1;
          setsockopt(master_, IPPROTO_TCP, TCP_NODELAY, &on, sizeof(on));
        }
      } else {
        sockaddr_storage peer{};
        socklen_t length = sizeof(peer);
        const ssize_t received =
            ::recvfrom(listener_, buffer.data(), buffer.size(), 0, reinterpret_cast<sockaddr*>(&peer), &length);
        if (received > 0) {
          const auto* peer_bytes = reinterpret_cast<const std::uint8_t*>(&peer);
          udp_peer_.assign(peer_bytes, peer_bytes + length);
          decoder_.reset();  // a datagram holds whole frames
          handle_bytes(std::span{buffer}.first(static_cast<std::size_t>(received)));
        }
      }
    }
    drain_queue();
  }
}

}  // namespace duet::xcp::host
