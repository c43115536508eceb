#include "app_service.hpp"

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <deque>
#include <iostream>
#include <set>
#include <sstream>

#include "duet/app_channel/host/peer.hpp"

namespace duet::bridge {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using app_channel::host::Description;
using app_channel::host::ParameterReport;
using app_channel::host::Peer;
using app_channel::host::Sample;
using nlohmann::json;

namespace {

constexpr std::size_t max_clients = 16;
constexpr std::size_t client_queue_limit = 256;  // messages; past it a client loses samples
constexpr std::size_t max_request_size = 4096;

json item_json(const app_channel::host::ItemDescription& item) {
  return {{"name", item.name},
          {"unit", item.unit},
          {"type", app_channel::host::name_of(item.type)},
          {"min", item.minimum},
          {"max", item.maximum}};
}

}  // namespace

class AppService::Impl {
 public:
  explicit Impl(AppServiceOptions options)
      : options_(std::move(options)),
        acceptor_(io_),
        retry_timer_(io_),
        status_timer_(io_),
        channel_(io_),
        input_(io_),
        peer_({.description = [this](const Description& description) { on_description(description); },
               .telemetry = [this](const Sample& sample) { on_sample(sample); },
               .parameter = [this](const ParameterReport& report) { on_parameter(report); },
               .problem = [this](const std::string& problem) { log("application channel: " + problem); }}) {}

  class Client;

  Status start() {
    if (options_.websocket) {
      beast::error_code error;
      const auto address = asio::ip::make_address(options_.listen_address, error);
      if (error) return Failure{"WebSocket address '" + options_.listen_address + "': " + error.message()};
      const tcp::endpoint endpoint{address, options_.websocket_port};
      if (acceptor_.open(endpoint.protocol(), error); !error) {
        acceptor_.set_option(asio::socket_base::reuse_address(true), error);
        if (acceptor_.bind(endpoint, error); !error) acceptor_.listen(asio::socket_base::max_listen_connections, error);
      }
      if (error) {
        return Failure{"cannot listen for WebSocket clients on " + options_.listen_address + ":" +
                       std::to_string(options_.websocket_port) + ": " + error.message()};
      }
      port_ = acceptor_.local_endpoint().port();
      accept();
    }
    if (options_.csv) read_input();
    open_channel();
    tick_status();
    return done();
  }

  void run() { io_.run(); }
  void stop() {
    asio::post(io_, [this] { io_.stop(); });
  }

  [[nodiscard]] std::uint16_t port() const { return port_; }

  [[nodiscard]] std::string status() const {
    json status = {{"type", "status"},
                   {"application_channel",
                    {{"open", channel_open_.load()},
                     {"opens", channel_opens_.load()},
                     {"samples", samples_.load()},
                     {"frames_lost", frames_lost_.load()},
                     {"garbage_bytes", garbage_bytes_.load()},
                     {"malformed_packets", malformed_.load()},
                     {"clients", clients_count_.load()},
                     {"samples_dropped_for_clients", dropped_for_clients_.load()}}}};
    if (options_.extra_status) {
      json extra = json::parse(options_.extra_status(), nullptr, false);
      if (extra.is_object()) status.update(extra);
    }
    return status.dump();
  }

  // Messages to every client; samples may be dropped for a slow one.
  void broadcast(const std::shared_ptr<const std::string>& message, bool droppable);
  void send_welcome(Client& client);
  void handle_request(Client& client, const std::string& text);
  void joined(const std::shared_ptr<Client>& client);
  void left(const std::shared_ptr<Client>& client);
  void count_dropped() { ++dropped_for_clients_; }

 private:
  void log(const std::string& line) const { std::cerr << "duet-bridge: " << line << std::endl; }

  void accept() {
    acceptor_.async_accept([this](beast::error_code error, tcp::socket socket) {
      if (error == asio::error::operation_aborted) return;
      if (!error) start_client(std::move(socket));
      accept();
    });
  }
  void start_client(tcp::socket socket);

  void open_channel() {
    auto opened = bridge::open_channel(options_.channel);
    if (!opened) {
      if (!channel_failing_) log("application channel " + options_.channel_uri + ": " + opened.error() + "; retrying");
      channel_failing_ = true;
      retry_in(retry_delay_);
      retry_delay_ = std::min(retry_delay_ * 2, std::chrono::milliseconds{2000});
      return;
    }
    channel_failing_ = false;
    retry_delay_ = std::chrono::milliseconds{100};
    channel_.assign(opened.value());
    channel_open_ = true;
    ++channel_opens_;
    peer_.reset();
    to_channel_.clear();
    log("application channel " + options_.channel_uri + " open");
    send_to_channel(peer_.describe_request());  // the firmware may have described itself before we were here
    read_channel();
  }

  void retry_in(std::chrono::milliseconds delay) {
    retry_timer_.expires_after(delay);
    retry_timer_.async_wait([this](beast::error_code error) {
      if (!error && !channel_.is_open()) open_channel();
      if (!error && channel_.is_open() && !to_channel_.empty() && !writing_channel_) write_channel();
    });
  }

  void close_channel(const std::string& reason) {
    if (!channel_.is_open()) return;
    beast::error_code ignored;
    channel_.close(ignored);
    channel_open_ = false;
    writing_channel_ = false;
    to_channel_.clear();
    log("application channel " + options_.channel_uri + " closed (" + reason + "); retrying");
    broadcast(std::make_shared<const std::string>(json{{"type", "channel"}, {"open", false}}.dump()), false);
    retry_in(retry_delay_);
  }

  void read_channel() {
    channel_.async_read_some(asio::buffer(read_buffer_), [this](beast::error_code error, std::size_t received) {
      if (error == asio::error::operation_aborted) return;
      if (error) return close_channel(error == asio::error::eof ? "end of file" : error.message());
      peer_.receive(std::span{read_buffer_}.first(received));
      const auto counters = peer_.counters();
      frames_lost_ = counters.frames_lost;
      garbage_bytes_ = counters.garbage_bytes;
      malformed_ = counters.malformed_packets;
      read_channel();
    });
  }

  void send_to_channel(const std::vector<std::uint8_t>& frame) {
    if (!channel_.is_open()) return;
    to_channel_.insert(to_channel_.end(), frame.begin(), frame.end());
    if (!writing_channel_) write_channel();
  }

  // At most one RPMsg payload per write; ENOMEM (no free RPMsg buffer) backs off and tries again.
  void write_channel() {
    writing_channel_ = true;
    const std::size_t chunk = std::min(to_channel_.size(), options_.channel_chunk);
    channel_.async_write_some(
        asio::buffer(to_channel_.data(), chunk), [this](beast::error_code error, std::size_t written) {
          if (error == asio::error::operation_aborted) return;
          writing_channel_ = false;
          if (error == asio::error::no_memory || error == asio::error::no_buffer_space) {
            return retry_in(std::chrono::milliseconds{1});
          }
          if (error) return close_channel(error.message());
          to_channel_.erase(to_channel_.begin(), to_channel_.begin() + static_cast<std::ptrdiff_t>(written));
          if (!to_channel_.empty()) write_channel();
        });
  }

  void on_description(const Description& description) {
    description_message_ = std::make_shared<const std::string>(description_json(description).dump());
    broadcast(description_message_, false);
    if (options_.verbose) {
      log("application " + description.application + ": " + std::to_string(description.telemetry.size()) +
          " telemetry signals, " + std::to_string(description.parameters.size()) + " parameters");
    }
    if (options_.csv) {
      std::string header = "sample";
      for (const auto& item : description.telemetry) {
        header += "," + item.name + (item.unit.empty() ? "" : " [" + item.unit + "]");
      }
      if (header != csv_header_) std::cout << header << '\n' << std::flush;  // a repeated description: no new header
      csv_header_ = header;
    }
  }

  void on_sample(const Sample& sample) {
    ++samples_;
    if (!clients_.empty()) {
      broadcast(std::make_shared<const std::string>(
                    json{{"type", "telemetry"}, {"sample", sample.sample}, {"values", sample.values}}.dump()),
                true);
    }
    if (options_.csv) {
      std::ostringstream line;
      line.precision(9);  // a float's every digit
      line << sample.sample;
      for (const double value : sample.values) line << ',' << value;
      std::cout << line.str() << '\n' << std::flush;
    }
  }

  void on_parameter(const ParameterReport& report) {
    const auto& description = peer_.description();
    json message = {
        {"type", "parameter"}, {"index", report.index}, {"status", app_channel::host::name_of(report.status)}};
    if (report.value) message["value"] = *report.value;
    if (description && report.index < description->parameters.size()) {
      message["name"] = description->parameters[report.index].name;
    }
    broadcast(std::make_shared<const std::string>(message.dump()), false);
    if (options_.csv && report.status != app_channel::ParameterStatus::reported && message.contains("name")) {
      log("parameter " + message["name"].get<std::string>() + " = " + (report.value ? message["value"].dump() : "?") +
          " (" + std::string{app_channel::host::name_of(report.status)} + ")");
    }
  }

  [[nodiscard]] json description_json(const Description& description) const {
    json message = {{"type", "description"},
                    {"application", description.application},
                    {"telemetry_period_us", description.telemetry_period_us},
                    {"telemetry", json::array()},
                    {"parameters", json::array()}};
    for (const auto& item : description.telemetry) message["telemetry"].push_back(item_json(item));
    for (const auto& item : description.parameters) message["parameters"].push_back(item_json(item));
    return message;
  }

  // `name=value` lines on standard input set parameters (CSV mode, for scripts).
  void read_input() {
    beast::error_code error;
    input_.assign(::dup(STDIN_FILENO), error);
    if (error) return;  // a regular file or nothing: no sets from standard input
    read_input_line();
  }
  void read_input_line() {
    asio::async_read_until(input_, asio::dynamic_buffer(input_line_, max_request_size), '\n',
                           [this](beast::error_code error, std::size_t length) {
                             if (error) return;  // end of input, or a line too long: stop listening
                             std::string line = input_line_.substr(0, length - 1);
                             input_line_.erase(0, length);
                             set_from_line(line);
                             read_input_line();
                           });
  }
  void set_from_line(const std::string& line) {
    const std::size_t equals = line.find('=');
    if (line.empty()) return;
    double value = 0;
    std::istringstream number{equals == std::string::npos ? std::string{} : line.substr(equals + 1)};
    if (equals == std::string::npos || !(number >> value)) {
      log("standard input: '" + line + "': expected name=value");
      return;
    }
    auto request = peer_.set_request(line.substr(0, equals), value);
    if (!request) return log("standard input: " + request.error());
    send_to_channel(request.value());
  }

  void tick_status() {
    status_timer_.expires_after(std::chrono::seconds{1});
    status_timer_.async_wait([this](beast::error_code error) {
      if (error) return;
      if (!clients_.empty()) broadcast(std::make_shared<const std::string>(status()), true);
      tick_status();
    });
  }

  AppServiceOptions options_;
  asio::io_context io_;
  tcp::acceptor acceptor_;
  asio::steady_timer retry_timer_;
  asio::steady_timer status_timer_;
  asio::posix::stream_descriptor channel_;
  asio::posix::stream_descriptor input_;
  std::string input_line_;
  std::array<std::uint8_t, 4096> read_buffer_{};
  std::vector<std::uint8_t> to_channel_;
  bool writing_channel_ = false;
  bool channel_failing_ = false;
  std::chrono::milliseconds retry_delay_{100};
  Peer peer_;
  std::shared_ptr<const std::string> description_message_;
  std::string csv_header_;
  std::set<std::shared_ptr<Client>> clients_;
  std::uint16_t port_ = 0;

  std::atomic<bool> channel_open_{false};
  std::atomic<std::uint64_t> channel_opens_{0}, samples_{0}, frames_lost_{0}, garbage_bytes_{0}, malformed_{0},
      clients_count_{0}, dropped_for_clients_{0};
};

// One WebSocket client: reads requests, writes messages from a bounded queue, one write at a time.
class AppService::Impl::Client : public std::enable_shared_from_this<Client> {
 public:
  Client(Impl& service, tcp::socket socket) : service_(service), socket_(std::move(socket)) {}

  void start() {
    socket_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    socket_.read_message_max(max_request_size);
    socket_.async_accept([self = shared_from_this()](beast::error_code error) {
      if (error) return;
      self->service_.joined(self);
    });
  }

  void read() {
    socket_.async_read(buffer_, [self = shared_from_this()](beast::error_code error, std::size_t) {
      if (error) return self->service_.left(self);
      const std::string text = beast::buffers_to_string(self->buffer_.data());
      self->buffer_.consume(self->buffer_.size());
      self->service_.handle_request(*self, text);
      self->read();
    });
  }

  void send(std::shared_ptr<const std::string> message, bool droppable) {
    if (closing_) return;
    if (droppable && outgoing_.size() >= client_queue_limit) {
      service_.count_dropped();
      return;
    }
    outgoing_.push_back(std::move(message));
    if (outgoing_.size() == 1) write();
  }

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
                          if (error) return self->service_.left(self);
                          self->outgoing_.pop_front();
                          if (!self->outgoing_.empty()) self->write();
                        });
  }

  Impl& service_;
  websocket::stream<tcp::socket> socket_;
  beast::flat_buffer buffer_;
  std::deque<std::shared_ptr<const std::string>> outgoing_;
  bool closing_ = false;
};

void AppService::Impl::start_client(tcp::socket socket) { std::make_shared<Client>(*this, std::move(socket))->start(); }

void AppService::Impl::joined(const std::shared_ptr<Client>& client) {
  if (clients_.size() >= max_clients) {
    log("refused a WebSocket client: " + std::to_string(max_clients) + " are connected");
    client->refuse("too many clients");
    return;
  }
  clients_.insert(client);
  clients_count_ = clients_.size();
  send_welcome(*client);
  client->read();
}

void AppService::Impl::left(const std::shared_ptr<Client>& client) {
  clients_.erase(client);
  clients_count_ = clients_.size();
}

void AppService::Impl::send_welcome(Client& client) {
  if (description_message_) client.send(description_message_, false);
  const auto& description = peer_.description();
  const auto& values = peer_.parameter_values();
  for (std::size_t index = 0; description && index < values.size(); ++index) {
    if (!values[index]) continue;
    client.send(std::make_shared<const std::string>(json{
                    {"type", "parameter"},
                    {"index", index},
                    {"name", description->parameters[index].name},
                    {"value", *values[index]},
                    {"status", "reported"}}.dump()),
                false);
  }
}

void AppService::Impl::broadcast(const std::shared_ptr<const std::string>& message, bool droppable) {
  for (const auto& client : clients_) client->send(message, droppable);
}

void AppService::Impl::handle_request(Client& client, const std::string& text) {
  const auto answer_error = [&client](const std::string& message) {
    client.send(std::make_shared<const std::string>(json{{"type", "error"}, {"message", message}}.dump()), false);
  };
  const json request = json::parse(text, nullptr, false);
  if (!request.is_object() || !request.contains("type") || !request["type"].is_string()) {
    return answer_error("a request is a JSON object with a \"type\": set, describe or status");
  }
  const std::string type = request["type"].get<std::string>();
  if (type == "status") return client.send(std::make_shared<const std::string>(status()), false);
  if (type == "describe") {
    if (!channel_.is_open()) return answer_error("the application channel is not open");
    return send_to_channel(peer_.describe_request());
  }
  if (type == "set") {
    if (!request.contains("name") || !request["name"].is_string() || !request.contains("value") ||
        !request["value"].is_number()) {
      return answer_error("set needs \"name\" (a string) and \"value\" (a number)");
    }
    if (!channel_.is_open()) return answer_error("the application channel is not open");
    auto frame = peer_.set_request(request["name"].get<std::string>(), request["value"].get<double>());
    if (!frame) return answer_error(frame.error());
    return send_to_channel(frame.value());
  }
  answer_error("unknown request type '" + type + "': set, describe or status");
}

AppService::AppService(AppServiceOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
AppService::~AppService() = default;
Status AppService::start() { return impl_->start(); }
void AppService::run() { impl_->run(); }
void AppService::stop() { impl_->stop(); }
std::uint16_t AppService::websocket_port() const { return impl_->port(); }
std::string AppService::status() const { return impl_->status(); }

}  // namespace duet::bridge
