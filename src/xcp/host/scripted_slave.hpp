#pragma once
// A slave that is nothing but a script, for testing the master against layouts duet's slave does not produce: for
// each request the master must send (exact bytes), the packets it answers with (exact bytes, fill included), framed
// for XCP on TCP by hand (LEN and CTR little-endian, LEN counting every byte of the packet). Test code only.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace duet::xcp::host {

struct ScriptStep {
  std::string request;               // hex, as the standard lays the command out
  std::vector<std::string> answers;  // hex packets: the response, then any DAQ or event packets
};

class ScriptedSlave {
 public:
  explicit ScriptedSlave(std::vector<ScriptStep> script) : script_(std::move(script)) {
    listener_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(listener_, reinterpret_cast<sockaddr*>(&address), sizeof(address));
    ::listen(listener_, 1);
    socklen_t length = sizeof(address);
    ::getsockname(listener_, reinterpret_cast<sockaddr*>(&address), &length);
    port_ = ntohs(address.sin_port);
    thread_ = std::thread{[this] { serve(); }};
  }
  ~ScriptedSlave() {
    if (thread_.joinable()) thread_.join();
    ::close(listener_);
  }
  ScriptedSlave(const ScriptedSlave&) = delete;
  ScriptedSlave& operator=(const ScriptedSlave&) = delete;

  [[nodiscard]] std::uint16_t port() const { return port_; }

  // Waits until the master has gone and tells where it left the script: "" if it sent every request as written and
  // nothing more.
  std::string differences() {
    if (thread_.joinable()) thread_.join();
    return differences_;
  }

 private:
  static std::vector<std::uint8_t> bytes_of(const std::string& hex) {
    std::vector<std::uint8_t> bytes;
    std::istringstream stream{hex};
    std::string byte;
    while (stream >> byte) bytes.push_back(static_cast<std::uint8_t>(std::stoul(byte, nullptr, 16)));
    return bytes;
  }
  static std::string hex_of(const std::vector<std::uint8_t>& bytes) {
    std::string text;
    static constexpr char digits[] = "0123456789ABCDEF";
    for (std::uint8_t byte : bytes) {
      if (!text.empty()) text += ' ';
      text += digits[byte >> 4U];
      text += digits[byte & 0xFU];
    }
    return text;
  }

  // Reads exactly `count` bytes, giving up after 5 s without any.
  static bool read_exactly(int socket, std::uint8_t* into, std::size_t count) {
    std::size_t got = 0;
    while (got < count) {
      pollfd waiting{socket, POLLIN, 0};
      if (::poll(&waiting, 1, 5000) != 1) return false;
      const ssize_t received = ::recv(socket, into + got, count - got, 0);
      if (received <= 0) return false;
      got += static_cast<std::size_t>(received);
    }
    return true;
  }

  // The next packet the master sends, or nothing when it closed the connection.
  static std::optional<std::vector<std::uint8_t>> next_request(int socket) {
    std::uint8_t header[4];
    if (!read_exactly(socket, header, sizeof(header))) return std::nullopt;
    std::vector<std::uint8_t> packet(static_cast<std::size_t>(header[0] | (header[1] << 8U)));
    if (!read_exactly(socket, packet.data(), packet.size())) return std::nullopt;
    return packet;
  }

  void send_packet(int socket, const std::vector<std::uint8_t>& packet) {
    std::vector<std::uint8_t> frame{static_cast<std::uint8_t>(packet.size()),
                                    static_cast<std::uint8_t>(packet.size() >> 8U), static_cast<std::uint8_t>(counter_),
                                    static_cast<std::uint8_t>(counter_ >> 8U)};
    ++counter_;
    frame.insert(frame.end(), packet.begin(), packet.end());
    (void)::send(socket, frame.data(), frame.size(), MSG_NOSIGNAL);
  }

  void serve() {
    pollfd waiting{listener_, POLLIN, 0};
    if (::poll(&waiting, 1, 5000) != 1) {
      differences_ = "no master connected";
      return;
    }
    const int master = ::accept4(listener_, nullptr, nullptr, SOCK_CLOEXEC);
    for (std::size_t step = 0; step < script_.size() && differences_.empty(); ++step) {
      const auto request = next_request(master);
      if (!request) {
        differences_ = "the master stopped before request " + std::to_string(step) + " (" + script_[step].request + ")";
      } else if (hex_of(*request) != script_[step].request) {
        differences_ =
            "request " + std::to_string(step) + ": expected " + script_[step].request + ", got " + hex_of(*request);
      } else {
        for (const std::string& answer : script_[step].answers) send_packet(master, bytes_of(answer));
      }
    }
    if (differences_.empty()) {
      if (const auto extra = next_request(master)) differences_ = "a request beyond the script: " + hex_of(*extra);
    }
    ::close(master);
  }

  std::vector<ScriptStep> script_;
  int listener_ = -1;
  std::uint16_t port_ = 0;
  std::uint16_t counter_ = 0;
  std::string differences_;
  std::thread thread_;
};

}  // namespace duet::xcp::host
