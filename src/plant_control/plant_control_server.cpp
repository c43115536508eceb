#include "duet/plant_control/plant_control_server.hpp"

#include <boost/asio.hpp>
#include <nlohmann/json.hpp>

#include <deque>
#include <map>
#include <set>
#include <thread>

#include "duet/plant_control/plant_messages.hpp"

namespace duet::plant_control {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using nlohmann::json;
using error_code = boost::system::error_code;

namespace {

constexpr std::size_t longest_line = 4096;

}  // namespace

class PlantControlServer::Impl : public std::enable_shared_from_this<Impl> {
 public:
  class Connection;

  Impl(plant::PlantControls& controls, ServerOptions options)
      : controls_(controls), options_(std::move(options)), acceptor_(io_) {}

  Status listen() {
    error_code error;
    const std::string host = options_.host == "localhost" ? "127.0.0.1" : options_.host;
    const auto address = asio::ip::make_address(host, error);
    if (error) return Failure{"plant control: address '" + options_.host + "': " + error.message()};
    if (!address.is_loopback()) {
      return Failure{"plant control: " + options_.host +
                     " is not this machine's loopback address: the endpoint "
                     "serves this machine only"};
    }
    const tcp::endpoint endpoint{address, options_.port};
    if (acceptor_.open(endpoint.protocol(), error); !error) {
      acceptor_.set_option(asio::socket_base::reuse_address(true), error);
      if (acceptor_.bind(endpoint, error); !error) acceptor_.listen(asio::socket_base::max_listen_connections, error);
    }
    if (error) {
      return Failure{"plant control: cannot listen on " + options_.host + ":" + std::to_string(options_.port) + ": " +
                     error.message()};
    }
    const tcp::endpoint bound = acceptor_.local_endpoint();
    address_ = (bound.address().is_v6() ? "[" + bound.address().to_string() + "]" : bound.address().to_string()) + ":" +
               std::to_string(bound.port());
    description_ = description_message(options_.plant, controls_.offered()).dump() + "\n";
    accept();
    thread_ = std::thread{[this] { io_.run(); }};
    return done();
  }

  void stop() {
    asio::post(io_, [this] {
      error_code ignored;
      acceptor_.close(ignored);
      for (const auto& [ticket, waiting] : waiting_) controls_.withdraw(ticket);
      waiting_.clear();
      io_.stop();
    });
    if (thread_.joinable()) thread_.join();
  }

  [[nodiscard]] const std::string& address() const { return address_; }

 private:
  struct Waiting {
    std::weak_ptr<Connection> asker;
    std::string action;
    std::string id;  // the asker's, as JSON text, given back with its answer; empty: none
    std::unique_ptr<asio::steady_timer> timer;
  };
  // The asker's answer: `message` with its id.
  static void tell(const Waiting& waiting, json message);

  void accept();
  void handle(const std::shared_ptr<Connection>& connection, const std::string& line);
  void answer(plant::PlantControls::Ticket ticket, const Result<plant::AppliedDisturbance>& outcome);
  void give_up(plant::PlantControls::Ticket ticket);

  plant::PlantControls& controls_;
  ServerOptions options_;
  asio::io_context io_;
  tcp::acceptor acceptor_;
  std::string address_;
  std::string description_;
  std::set<std::shared_ptr<Connection>> connections_;
  std::map<plant::PlantControls::Ticket, Waiting> waiting_;
  std::thread thread_;
};

// One client: lines in, lines out, one write at a time.
class PlantControlServer::Impl::Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(Impl& server, tcp::socket socket) : server_(server), socket_(std::move(socket)) {}

  void start() {
    send(server_.description_);
    read();
  }

  void send(std::string line) {
    outgoing_.push_back(std::move(line));
    if (outgoing_.size() == 1) write();
  }
  void send(const json& message) { send(message.dump() + "\n"); }

  void close() {
    error_code ignored;
    socket_.close(ignored);
    server_.connections_.erase(shared_from_this());
  }

 private:
  void read() {
    asio::async_read_until(
        socket_, asio::dynamic_buffer(input_, longest_line), '\n',
        [self = shared_from_this()](error_code error, std::size_t length) {
          if (error == asio::error::not_found) {  // no newline within the limit: not this protocol
            self->send(json{{"type", "error"},
                            {"message", "a line is at most " + std::to_string(longest_line) + " bytes; closing"}});
            return self->close_after_writing();
          }
          if (error) return self->close();
          std::string line = self->input_.substr(0, length - 1);
          self->input_.erase(0, length);
          if (!line.empty() && line.back() == '\r') line.pop_back();
          if (!line.empty()) self->server_.handle(self, line);
          self->read();
        });
  }

  void write() {
    asio::async_write(socket_, asio::buffer(outgoing_.front()),
                      [self = shared_from_this()](error_code error, std::size_t) {
                        if (error) return self->close();
                        self->outgoing_.pop_front();
                        if (!self->outgoing_.empty()) return self->write();
                        if (self->closing_) self->close();
                      });
  }

  void close_after_writing() {
    closing_ = true;
    if (outgoing_.empty()) close();
  }

  Impl& server_;
  tcp::socket socket_;
  std::string input_;
  std::deque<std::string> outgoing_;
  bool closing_ = false;
};

void PlantControlServer::Impl::accept() {
  acceptor_.async_accept([this](error_code error, tcp::socket socket) {
    if (error == asio::error::operation_aborted) return;
    if (!error) {
      auto connection = std::make_shared<Connection>(*this, std::move(socket));
      if (connections_.size() >= options_.max_connections) {
        connection->send(json{{"type", "error"},
                              {"message", "at most " + std::to_string(options_.max_connections) + " connections"}});
      } else {
        connections_.insert(connection);
        connection->start();
      }
    }
    accept();
  });
}

void PlantControlServer::Impl::handle(const std::shared_ptr<Connection>& connection, const std::string& line) {
  const json request = json::parse(line, nullptr, false);
  if (!request.is_object() || !request.contains("type") || !request["type"].is_string()) {
    return connection->send(
        json{{"type", "error"}, {"message", "a request is a JSON object with a \"type\" on one line"}});
  }
  const std::string type = request["type"].get<std::string>();
  if (type == "describe") return connection->send(description_);
  if (type != "plant") {
    return connection->send(
        json{{"type", "error"}, {"message", "unknown request type '" + type + "': plant or describe"}});
  }
  const json id = request.contains("id") ? request["id"] : json{};
  const auto refuse = [&](const std::string& problem) {
    json message = refused_message(request, problem);
    if (!id.is_null()) message["id"] = id;
    connection->send(message);
  };
  auto disturbance = read_request(request, controls_.offered());
  if (!disturbance) return refuse(disturbance.error());
  const std::string disturbance_name = disturbance.value().name;
  // The answer comes from the plant's thread, possibly when this server is gone: only a live server takes it, on its
  // own thread, where the ticket is known by then.
  auto ticket_box = std::make_shared<plant::PlantControls::Ticket>(0);
  const std::weak_ptr<Impl> weak = weak_from_this();
  auto ticket = controls_.request(std::move(disturbance).value(),
                                  [weak, ticket_box](const Result<plant::AppliedDisturbance>& outcome) {
                                    const std::shared_ptr<Impl> server = weak.lock();
                                    if (!server) return;
                                    asio::post(server->io_, [weak, ticket_box, outcome] {
                                      if (const std::shared_ptr<Impl> alive = weak.lock())
                                        alive->answer(*ticket_box, outcome);
                                    });
                                  });
  if (!ticket) return refuse(ticket.error());
  *ticket_box = ticket.value();
  Waiting& waiting =
      waiting_
          .emplace(ticket.value(), Waiting{connection, disturbance_name, id.is_null() ? std::string{} : id.dump(),
                                           std::make_unique<asio::steady_timer>(io_, options_.apply_within)})
          .first->second;
  waiting.timer->async_wait([weak, number = ticket.value()](error_code error) {
    if (error) return;
    if (const std::shared_ptr<Impl> alive = weak.lock()) alive->give_up(number);
  });
}

void PlantControlServer::Impl::answer(plant::PlantControls::Ticket ticket,
                                      const Result<plant::AppliedDisturbance>& outcome) {
  const auto found = waiting_.find(ticket);
  if (found == waiting_.end()) return;  // given up already
  Waiting waiting = std::move(found->second);
  waiting_.erase(found);
  waiting.timer->cancel();
  if (!outcome) return tell(waiting, refused_message({{"action", waiting.action}}, outcome.error()));
  const std::shared_ptr<Connection> asker = waiting.asker.lock();
  const json applied = applied_message(outcome.value(), controls_.offered());
  for (const auto& connection : connections_) {
    if (connection != asker) connection->send(applied);  // news for the others
  }
  tell(waiting, applied);
}

void PlantControlServer::Impl::give_up(plant::PlantControls::Ticket ticket) {
  const auto found = waiting_.find(ticket);
  if (found == waiting_.end() || !controls_.withdraw(ticket)) return;  // answered, or its answer is on the way
  tell(found->second,
       refused_message({{"action", found->second.action}}, "not applied: the plant did not advance within " +
                                                               std::to_string(options_.apply_within.count()) +
                                                               " ms (is the firmware running?)"));
  waiting_.erase(found);
}

void PlantControlServer::Impl::tell(const Waiting& waiting, json message) {
  const std::shared_ptr<Connection> asker = waiting.asker.lock();
  if (!asker) return;
  if (!waiting.id.empty()) message["id"] = json::parse(waiting.id);
  asker->send(message);
}

Result<std::unique_ptr<PlantControlServer>> PlantControlServer::start(plant::PlantControls& controls,
                                                                      ServerOptions options) {
  auto impl = std::make_shared<Impl>(controls, std::move(options));
  if (Status listening = impl->listen(); !listening) return Failure{listening.error()};
  return std::unique_ptr<PlantControlServer>{new PlantControlServer{std::move(impl)}};
}

PlantControlServer::PlantControlServer(std::shared_ptr<Impl> impl) : impl_(std::move(impl)) {}
PlantControlServer::~PlantControlServer() { impl_->stop(); }
const std::string& PlantControlServer::address() const { return impl_->address(); }

}  // namespace duet::plant_control
