#pragma once
// For tests: a WebSocket client of a dashboard back end (duet-bridge, duet monitor), as far as the tests need one.

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>
#include <sys/socket.h>

#include <chrono>
#include <optional>
#include <string>

namespace duet::dashboard::testing {

// Synchronous; every read is bounded by a receive timeout.
class WebSocketClient {
  using json = nlohmann::json;

 public:
  explicit WebSocketClient(std::uint16_t port) {
    socket_.next_layer().connect({boost::asio::ip::make_address("127.0.0.1"), port});
    const timeval patience{5, 0};
    ::setsockopt(socket_.next_layer().native_handle(), SOL_SOCKET, SO_RCVTIMEO, &patience, sizeof(patience));
    socket_.handshake("127.0.0.1", "/");
  }
  void send(const json& request) { socket_.write(boost::asio::buffer(request.dump())); }
  void send_text(const std::string& text) { socket_.write(boost::asio::buffer(text)); }
  // The next message of `type`, skipping others; none if none comes within `patience`.
  std::optional<json> next(const std::string& type, std::chrono::seconds patience = std::chrono::seconds{5}) {
    const auto deadline = std::chrono::steady_clock::now() + patience;
    while (std::chrono::steady_clock::now() < deadline) {
      boost::beast::flat_buffer buffer;
      boost::beast::error_code error;
      socket_.read(buffer, error);
      if (error) return std::nullopt;
      json message = json::parse(boost::beast::buffers_to_string(buffer.data()));
      if (message["type"] == type) return message;
    }
    return std::nullopt;
  }
  // The next report on parameter `name` that answers a set.
  std::optional<json> answer_on(const std::string& name) {
    while (auto report = next("parameter")) {
      if ((*report)["name"] == name && (*report)["status"] != "reported") return report;
    }
    return std::nullopt;
  }

 private:
  boost::asio::io_context io_;
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket> socket_{io_};
};

}  // namespace duet::dashboard::testing
