#pragma once
// The dashboard's way to a simulated plant (docs/DASHBOARD.md, "Disturbing a simulated plant"): a client of the
// plant-control endpoint that duet pil and duet plant serve offer (JSON lines over TCP, docs/LINK.md). It keeps the
// plant's description while the endpoint is reachable (connecting again, 100 ms doubling to 2 s, when it is not),
// relays the page's `plant` requests to it and its answers back: applied ones to every client, refusals to the one
// that asked. Shared by both back ends through Dashboard. Runs on the dashboard's io_context.

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "duet/dashboard/dashboard.hpp"

namespace duet::dashboard {

class PlantRelay {
 public:
  struct Handlers {
    std::function<void()> described;                     // description() changed: came, or went
    std::function<void(const nlohmann::json&)> applied;  // a `plant` event for every client
  };
  static constexpr std::chrono::seconds answer_within{4};  // longer than the endpoint waits for the plant

  PlantRelay(boost::asio::io_context& io, PlantControlAddress address, Handlers handlers);
  void start();
  void close();

  // The description's `plant` member, {name, actions}, while the endpoint is reachable.
  [[nodiscard]] const std::optional<nlohmann::json>& description() const { return description_; }
  // A page's {"type": "plant", "action": ..., arguments by name}.
  void request(Client& client, const nlohmann::json& request);
  // The status message's `plant` member: the link and the counters.
  [[nodiscard]] nlohmann::json status() const;

 private:
  struct Pending {
    std::weak_ptr<Client> client;
    std::string action;  // as asked for, for the refusal
    std::unique_ptr<boost::asio::steady_timer> timer;
  };

  void connect();
  void read();
  void on_line(const std::string& line);
  void lost(const std::string& problem);
  void retry();
  void write();
  void refuse(const std::weak_ptr<Client>& client, const std::string& action, const std::string& problem);

  boost::asio::io_context& io_;
  PlantControlAddress address_;
  Handlers handlers_;
  boost::asio::ip::tcp::resolver resolver_;
  boost::asio::ip::tcp::socket socket_;
  boost::asio::steady_timer retry_timer_;
  std::chrono::milliseconds retry_delay_{100};
  std::string input_;
  std::string output_;   // being written
  std::string waiting_;  // to write after it
  bool connected_ = false;
  bool closed_ = false;
  std::string problem_;
  std::optional<nlohmann::json> description_;
  std::uint64_t next_id_ = 1;
  std::map<std::uint64_t, Pending> pending_;
  std::uint64_t requests_ = 0, applied_ = 0, refused_ = 0, unreachable_ = 0, unanswered_ = 0, connects_ = 0;
};

}  // namespace duet::dashboard
