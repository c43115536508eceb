#include "plant_relay.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/read_until.hpp>
#include <boost/asio/write.hpp>

namespace duet::dashboard {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using nlohmann::json;
using error_code = boost::system::error_code;

namespace {

constexpr std::size_t longest_line = 65536;  // a description of many actions; more is not the endpoint
constexpr std::chrono::milliseconds longest_retry{2000};

}  // namespace

PlantRelay::PlantRelay(asio::io_context& io, PlantControlAddress address, Handlers handlers)
    : io_(io),
      address_(std::move(address)),
      handlers_(std::move(handlers)),
      resolver_(io),
      socket_(io),
      retry_timer_(io) {}

void PlantRelay::start() { connect(); }

void PlantRelay::close() {
  closed_ = true;
  error_code ignored;
  socket_.close(ignored);
  resolver_.cancel();
  retry_timer_.cancel();
  for (auto& [id, pending] : pending_) pending.timer->cancel();
  pending_.clear();
}

void PlantRelay::connect() {
  resolver_.async_resolve(address_.host, std::to_string(address_.port),
                          [this](error_code error, const tcp::resolver::results_type& found) {
                            if (error == asio::error::operation_aborted || closed_) return;
                            if (error) return lost(error.message());
                            asio::async_connect(socket_, found, [this](error_code connect_error, const tcp::endpoint&) {
                              if (connect_error == asio::error::operation_aborted || closed_) return;
                              if (connect_error) return lost(connect_error.message());
                              connected_ = true;
                              ++connects_;
                              problem_.clear();
                              retry_delay_ = std::chrono::milliseconds{100};
                              read();  // the endpoint describes the plant first
                            });
                          });
}

void PlantRelay::read() {
  asio::async_read_until(
      socket_, asio::dynamic_buffer(input_, longest_line), '\n', [this](error_code error, std::size_t length) {
        if (error == asio::error::operation_aborted || closed_) return;
        if (error == asio::error::not_found) return lost("a line longer than 64 KB");
        if (error) {
          return lost(error == asio::error::eof ? "the endpoint closed the connection" : error.message());
        }
        const std::string line = input_.substr(0, length - 1);
        input_.erase(0, length);
        on_line(line);
        if (connected_) read();
      });
}

void PlantRelay::on_line(const std::string& line) {
  const json message = json::parse(line, nullptr, false);
  if (!message.is_object() || !message.contains("type")) return lost("the endpoint sent what is not a JSON object");
  if (message["type"] == "description") {
    description_ = json{{"name", message.value("plant", "")}, {"actions", message.value("actions", json::array())}};
    if (handlers_.described) handlers_.described();
    return;
  }
  if (message["type"] != "plant") return;  // `error`: about a request of ours, which carry ids; nothing to relay
  json answer = message;
  std::optional<Pending> pending;
  if (message.contains("id") && message["id"].is_number_unsigned()) {
    const auto found = pending_.find(message["id"].get<std::uint64_t>());
    if (found != pending_.end()) {
      pending = std::move(found->second);
      pending_.erase(found);
      pending->timer->cancel();
    }
    answer.erase("id");
  }
  if (answer.contains("error")) {
    ++refused_;
    if (pending) {
      if (const std::shared_ptr<Client> client = pending->client.lock()) {
        client->send(dashboard::message(answer), Delivery::always);
      }
    }
    return;
  }
  if (pending) ++applied_;
  if (handlers_.applied) handlers_.applied(answer);  // ours or another dashboard's: every page shows the last one
}

void PlantRelay::lost(const std::string& problem) {
  const bool was_connected = connected_;
  problem_ = problem;
  connected_ = false;
  error_code ignored;
  socket_.close(ignored);
  input_.clear();
  output_.clear();
  waiting_.clear();
  for (auto& [id, pending] : pending_) {
    pending.timer->cancel();
    ++unanswered_;
    refuse(pending.client, pending.action, "the plant-control endpoint went away: " + problem);
  }
  pending_.clear();
  if (description_) {
    description_.reset();
    if (handlers_.described) handlers_.described();
  }
  if (was_connected) retry_delay_ = std::chrono::milliseconds{100};
  retry();
}

void PlantRelay::retry() {
  retry_timer_.expires_after(retry_delay_);
  retry_delay_ = std::min(retry_delay_ * 2, longest_retry);
  retry_timer_.async_wait([this](error_code error) {
    if (!error && !closed_) connect();
  });
}

void PlantRelay::request(Client& client, const json& request) {
  ++requests_;
  const std::string action =
      request.contains("action") && request["action"].is_string() ? request["action"].get<std::string>() : "";
  if (!connected_ || !description_) {
    ++unreachable_;
    return refuse(client.handle(), action,
                  "the plant is not reachable at " + address_.host + ":" + std::to_string(address_.port) +
                      (problem_.empty() ? std::string{} : " (" + problem_ + ")"));
  }
  if (action.empty()) {
    ++refused_;
    std::string names;
    for (const json& offered : (*description_)["actions"]) {
      names += (names.empty() ? "" : ", ") + offered.value("name", "");
    }
    return refuse(client.handle(), action, "a plant request needs \"action\": " + names);
  }
  const std::uint64_t id = next_id_++;
  json relayed = request;
  relayed["id"] = id;
  Pending& pending =
      pending_.emplace(id, Pending{client.handle(), action, std::make_unique<asio::steady_timer>(io_, answer_within)})
          .first->second;
  pending.timer->async_wait([this, id](error_code error) {
    if (error) return;
    const auto found = pending_.find(id);
    if (found == pending_.end()) return;
    ++unanswered_;
    refuse(found->second.client, found->second.action,
           "the plant did not answer within " + std::to_string(answer_within.count()) + " s");
    pending_.erase(found);
  });
  waiting_ += relayed.dump() + "\n";
  if (output_.empty()) write();
}

void PlantRelay::write() {
  output_ = std::exchange(waiting_, {});
  asio::async_write(socket_, asio::buffer(output_), [this](error_code error, std::size_t) {
    if (error == asio::error::operation_aborted || closed_) return;
    if (error) return lost(error.message());
    output_.clear();
    if (!waiting_.empty()) write();
  });
}

void PlantRelay::refuse(const std::weak_ptr<Client>& client, const std::string& action, const std::string& problem) {
  const std::shared_ptr<Client> asker = client.lock();
  if (!asker) return;
  json message = {{"type", "plant"}, {"error", problem}};
  if (!action.empty()) message["action"] = action;
  asker->send(dashboard::message(message), Delivery::always);
}

json PlantRelay::status() const {
  json link = {{"state", connected_ ? "open" : "connecting"},
               {"address", address_.host + ":" + std::to_string(address_.port)}};
  if (!problem_.empty()) link["problem"] = problem_;
  return {{"link", link},        {"connects", connects_},       {"requests", requests_},    {"applied", applied_},
          {"refused", refused_}, {"unreachable", unreachable_}, {"unanswered", unanswered_}};
}

}  // namespace duet::dashboard
