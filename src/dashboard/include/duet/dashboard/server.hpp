#pragma once
// The dashboard's server: the front end's files over HTTP and the JSON protocol over WebSocket, on one port
// (docs/DASHBOARD.md), and the few HTTP requests its owner answers (the MDF4 files). What the messages say is the back
// end's business (the bridge's application channel, duet monitor's XCP master); this is the serving: files from one
// folder only, a bounded queue per client that drops what may be dropped (samples, status) and never what may not, at
// most `max_clients` clients. Runs on the caller's io_context; every member is called on that context's thread, except
// the counters.

#include <nlohmann/json_fwd.hpp>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "duet/support/result.hpp"

namespace boost::asio {
class io_context;
}

namespace duet::dashboard {

struct ServerOptions {
  std::string address = "127.0.0.1";
  std::uint16_t port = 0;          // 0: any free port
  std::filesystem::path web_root;  // the built front end (web/dist); empty: WebSocket only
  std::string log_name = "dashboard";
  std::string index = "index.html";                     // the page "/" is
  std::size_t max_request_size = 4096;                  // bytes of one WebSocket request
  std::size_t max_upload_size = std::size_t{32} << 20;  // bytes of an HTTP request's body (answered 413 past it)
};

enum class Delivery { droppable, always };

using Message = std::shared_ptr<const std::string>;
Message message(const nlohmann::json& contents);

// A connected WebSocket client.
class Client {
 public:
  virtual ~Client() = default;
  virtual void send(Message message, Delivery delivery) = 0;
  void error(const std::string& text);  // an `error` message
  // For an answer that comes later: empty once the client has left.
  [[nodiscard]] virtual std::weak_ptr<Client> handle() = 0;
};

struct HttpRequest {
  std::string method;  // GET, HEAD, POST, ...
  std::string target;  // the path with its query
  std::string body;
};

struct HttpAnswer {
  unsigned status = 200;
  std::string content_type;
  std::string body;
  std::string attachment;  // a file name: the body is a download of that name
};

struct ServerHandlers {
  std::function<void(Client&)> joined;                          // send the welcome
  std::function<void(Client&, const nlohmann::json&)> request;  // a JSON object with a string `type`
  // An HTTP request the owner answers itself; none: the front end's files answer it.
  std::function<std::optional<HttpAnswer>(const HttpRequest&)> http;
};

class Server {
 public:
  static constexpr std::size_t max_clients = 16;
  static constexpr std::size_t queue_limit = 256;  // messages waiting for one client

  Server(boost::asio::io_context& io, ServerOptions options, ServerHandlers handlers);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // Binds and listens; fails naming the address.
  Status start();
  void close();
  [[nodiscard]] std::uint16_t port() const;

  void broadcast(const Message& message, Delivery delivery);
  [[nodiscard]] bool has_clients() const;

  // Thread-safe counters.
  [[nodiscard]] std::uint64_t clients() const { return clients_.load(); }
  [[nodiscard]] std::uint64_t dropped() const { return dropped_.load(); }
  [[nodiscard]] std::uint64_t files_served() const { return files_served_.load(); }

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  std::atomic<std::uint64_t> clients_{0}, dropped_{0}, files_served_{0};
};

}  // namespace duet::dashboard
