#include "duet/dashboard/server.hpp"

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <deque>
#include <iostream>
#include <optional>
#include <set>

#include "duet/dashboard/static_files.hpp"

namespace duet::dashboard {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using nlohmann::json;

Message message(const json& contents) { return std::make_shared<const std::string>(contents.dump()); }

void Client::error(const std::string& text) { send(message({{"type", "error"}, {"message", text}}), Delivery::always); }

namespace {

constexpr auto http_patience = std::chrono::seconds{30};

// The page when the front end has not been built: says how to build it rather than a bare 404.
constexpr std::string_view not_built =
    "<!doctype html><title>duet</title><p>The dashboard's page is not built. Run <code>npm ci && npm run build</code>"
    " in duet's <code>web/</code> folder, or give the back end <code>--web DIR</code>. The WebSocket API works"
    " without it (docs/DASHBOARD.md).</p>\n";

}  // namespace

class Server::Impl {
 public:
  class WebSocketClient;
  class HttpSession;

  Impl(asio::io_context& io, ServerOptions options, ServerHandlers handlers, Server& owner)
      : io_(io), options_(std::move(options)), handlers_(std::move(handlers)), owner_(owner), acceptor_(io) {}

  Status start() {
    beast::error_code error;
    const auto address = asio::ip::make_address(options_.address, error);
    if (error) return Failure{"address '" + options_.address + "': " + error.message()};
    const tcp::endpoint endpoint{address, options_.port};
    if (acceptor_.open(endpoint.protocol(), error); !error) {
      acceptor_.set_option(asio::socket_base::reuse_address(true), error);
      if (acceptor_.bind(endpoint, error); !error) acceptor_.listen(asio::socket_base::max_listen_connections, error);
    }
    if (error) {
      return Failure{"cannot listen on " + options_.address + ":" + std::to_string(options_.port) + ": " +
                     error.message()};
    }
    port_ = acceptor_.local_endpoint().port();
    accept();
    return done();
  }

  void close() {
    beast::error_code ignored;
    acceptor_.close(ignored);
  }

  [[nodiscard]] std::uint16_t port() const { return port_; }

  void broadcast(const Message& message, Delivery delivery);
  [[nodiscard]] bool has_clients() const { return !clients_.empty(); }

  void upgrade(tcp::socket socket, http::request<http::string_body> request);
  void joined(const std::shared_ptr<WebSocketClient>& client);
  void left(const std::shared_ptr<WebSocketClient>& client);
  void handle(WebSocketClient& client, const std::string& text);

  const ServerOptions& options() const { return options_; }
  const ServerHandlers& handlers() const { return handlers_; }
  Server& owner() { return owner_; }

 private:
  void accept();

  asio::io_context& io_;
  ServerOptions options_;
  ServerHandlers handlers_;
  Server& owner_;
  tcp::acceptor acceptor_;
  std::uint16_t port_ = 0;
  std::set<std::shared_ptr<WebSocketClient>> clients_;
};

// One WebSocket client: reads requests, writes messages from a bounded queue, one write at a time.
class Server::Impl::WebSocketClient final : public Client, public std::enable_shared_from_this<WebSocketClient> {
 public:
  WebSocketClient(Impl& server, tcp::socket socket) : server_(server), socket_(std::move(socket)) {}

  void start(http::request<http::string_body> request) {
    socket_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    socket_.read_message_max(server_.options().max_request_size);
    socket_.auto_fragment(false);  // a block of samples goes in one frame, not in 4 KB pieces
    socket_.async_accept(request, [self = shared_from_this()](beast::error_code error) {
      if (!error) self->server_.joined(self);
    });
  }

  void read() {
    socket_.async_read(buffer_, [self = shared_from_this()](beast::error_code error, std::size_t) {
      if (error) return self->server_.left(self);
      const std::string text = beast::buffers_to_string(self->buffer_.data());
      self->buffer_.consume(self->buffer_.size());
      self->server_.handle(*self, text);
      self->read();
    });
  }

  void send(Message message, Delivery delivery) override {
    if (closing_) return;
    if (delivery == Delivery::droppable && outgoing_.size() >= queue_limit) {
      ++server_.owner().dropped_;
      return;
    }
    outgoing_.push_back(std::move(message));
    if (outgoing_.size() == 1) write();
  }

  std::weak_ptr<Client> handle() override { return shared_from_this(); }

  void refuse(const std::string& reason) {
    closing_ = true;
    socket_.async_close(websocket::close_reason{websocket::close_code::try_again_later, reason},
                        [self = shared_from_this()](beast::error_code) {});
  }

 private:
  void write() {
    socket_.text(true);
    socket_.async_write(asio::buffer(*outgoing_.front()),
                        [self = shared_from_this()](beast::error_code error, std::size_t) {
                          if (error) return self->server_.left(self);
                          self->outgoing_.pop_front();
                          if (!self->outgoing_.empty()) self->write();
                        });
  }

  Impl& server_;
  websocket::stream<tcp::socket> socket_;
  beast::flat_buffer buffer_;
  std::deque<Message> outgoing_;
  bool closing_ = false;
};

// One HTTP connection: answers the owner's requests (ServerHandlers::http) and GET and HEAD with the front end's
// files until the client asks to upgrade to WebSocket, which hands the socket over.
class Server::Impl::HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(Impl& server, tcp::socket socket) : server_(server), stream_(std::move(socket)) {}

  void read() {
    parser_.emplace();
    parser_->body_limit(server_.options().max_upload_size);
    stream_.expires_after(http_patience);
    http::async_read(stream_, buffer_, *parser_, [self = shared_from_this()](beast::error_code error, std::size_t) {
      if (error == http::error::body_limit) return self->refuse_large_body();
      if (error) return;  // closed, timed out, or not HTTP: nothing to answer
      self->request_ = self->parser_->release();
      self->answer();
    });
  }

 private:
  void answer() {
    if (websocket::is_upgrade(request_)) {
      stream_.expires_never();
      return server_.upgrade(stream_.release_socket(), std::move(request_));
    }
    const bool keep_alive = request_.keep_alive();
    if (const auto& owners = server_.handlers().http; owners) {
      auto answer = owners(HttpRequest{std::string{request_.method_string()}, std::string{request_.target()},
                                       std::move(request_.body())});
      if (answer) return reply(std::move(*answer), keep_alive);
    }
    if (request_.method() != http::verb::get && request_.method() != http::verb::head) {
      return reply_text(http::status::method_not_allowed, "GET or HEAD only\n", keep_alive);
    }
    const auto& root = server_.options().web_root;
    std::string target{request_.target()};
    if (target == "/" || target.starts_with("/?")) target = "/" + server_.options().index;
    if (root.empty() || !std::filesystem::is_directory(root)) {
      if (target == "/" + server_.options().index)
        return reply_text(http::status::ok, std::string{not_built}, keep_alive, "text/html; charset=utf-8");
      return reply_text(http::status::not_found, "no such file\n", keep_alive);
    }
    auto file = file_for(root, target);
    if (!file) return reply_text(http::status::not_found, file.error() + "\n", keep_alive);
    beast::error_code error;
    http::file_body::value_type body;
    body.open(file.value().c_str(), beast::file_mode::scan, error);
    if (error) return reply_text(http::status::not_found, "cannot be read\n", keep_alive);
    const std::uint64_t size = body.size();
    auto response = std::make_shared<http::response<http::file_body>>(
        std::piecewise_construct, std::make_tuple(std::move(body)), std::make_tuple(http::status::ok, 11));
    response->set(http::field::content_type, std::string{content_type(file.value())});
    response->set(http::field::cache_control, "no-cache");  // a rebuilt front end shows at the next load
    response->content_length(size);
    response->keep_alive(keep_alive);
    if (request_.method() == http::verb::head) response->body().close();
    ++server_.owner().files_served_;
    send(response, request_.method() == http::verb::head);
  }

  // The rest of the body is not read: the connection ends after the answer.
  void refuse_large_body() {
    reply_text(http::status::payload_too_large,
               "the request's body is larger than " + std::to_string(server_.options().max_upload_size) + " bytes\n",
               false);
  }

  void reply(HttpAnswer answer, bool keep_alive) {
    auto response = std::make_shared<http::response<http::string_body>>(http::int_to_status(answer.status), 11);
    response->set(http::field::content_type, answer.content_type);
    response->set(http::field::cache_control, "no-store");
    if (!answer.attachment.empty())
      response->set(http::field::content_disposition, "attachment; filename=\"" + answer.attachment + "\"");
    response->body() = std::move(answer.body);
    response->prepare_payload();
    response->keep_alive(keep_alive);
    send(response, request_.method() == http::verb::head);
  }

  void reply_text(http::status status, std::string text, bool keep_alive,
                  std::string_view type = "text/plain; charset=utf-8") {
    auto response = std::make_shared<http::response<http::string_body>>(status, 11);
    response->set(http::field::content_type, std::string{type});
    response->body() = std::move(text);
    response->prepare_payload();
    response->keep_alive(keep_alive);
    send(response, false);
  }

  template <typename Response>
  void send(const std::shared_ptr<Response>& response, bool header_only) {
    const auto then = [self = shared_from_this(), response](beast::error_code error, std::size_t) {
      if (error || !response->keep_alive()) {
        beast::error_code ignored;
        self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
        return;
      }
      self->read();
    };
    if (header_only) {
      auto serializer = std::make_shared<http::response_serializer<typename Response::body_type>>(*response);
      http::async_write_header(stream_, *serializer,
                               [serializer, then](beast::error_code error, std::size_t n) { then(error, n); });
    } else {
      http::async_write(stream_, *response, then);
    }
  }

  Impl& server_;
  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;  // anew per request: a parser reads one
  http::request<http::string_body> request_;
};

void Server::Impl::accept() {
  acceptor_.async_accept([this](beast::error_code error, tcp::socket socket) {
    if (error == asio::error::operation_aborted) return;
    if (!error) std::make_shared<HttpSession>(*this, std::move(socket))->read();
    accept();
  });
}

void Server::Impl::upgrade(tcp::socket socket, http::request<http::string_body> request) {
  std::make_shared<WebSocketClient>(*this, std::move(socket))->start(std::move(request));
}

void Server::Impl::joined(const std::shared_ptr<WebSocketClient>& client) {
  if (clients_.size() >= max_clients) {
    std::cerr << options_.log_name << ": refused a WebSocket client: " << max_clients << " are connected" << std::endl;
    client->refuse("too many clients");
    return;
  }
  clients_.insert(client);
  owner_.clients_ = clients_.size();
  if (handlers_.joined) handlers_.joined(*client);
  client->read();
}

void Server::Impl::left(const std::shared_ptr<WebSocketClient>& client) {
  clients_.erase(client);
  owner_.clients_ = clients_.size();
}

void Server::Impl::handle(WebSocketClient& client, const std::string& text) {
  const json request = json::parse(text, nullptr, false);
  if (!request.is_object() || !request.contains("type") || !request["type"].is_string()) {
    return client.error("a request is a JSON object with a \"type\" (docs/DASHBOARD.md)");
  }
  if (handlers_.request) handlers_.request(client, request);
}

void Server::Impl::broadcast(const Message& message, Delivery delivery) {
  for (const auto& client : clients_) client->send(message, delivery);
}

Server::Server(asio::io_context& io, ServerOptions options, ServerHandlers handlers)
    : impl_(std::make_unique<Impl>(io, std::move(options), std::move(handlers), *this)) {}
Server::~Server() = default;
Status Server::start() { return impl_->start(); }
void Server::close() { impl_->close(); }
std::uint16_t Server::port() const { return impl_->port(); }
void Server::broadcast(const Message& message, Delivery delivery) { impl_->broadcast(message, delivery); }
bool Server::has_clients() const { return impl_->has_clients(); }

}  // namespace duet::dashboard
