#pragma once
// What both back ends of the dashboard share (docs/DASHBOARD.md): the server, the description and every
// parameter's last value that a client gets when it connects, samples to every client and to the recorder, the
// recorder's requests, status every second. A back end (the bridge's application channel, duet monitor's XCP
// master) tells it what the target said and answers `set`, `describe` and what its status is.
// Every member runs on the io_context's thread, except the counters.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "duet/dashboard/recorder.hpp"
#include "duet/dashboard/server.hpp"

namespace duet::dashboard {

struct Item {
  std::string name;
  std::string unit;
  std::string type;  // float32, uint16, ...
  double minimum = 0;
  double maximum = 0;
  // Value names (a state, a choice): shown instead of the value; empty: a number.
  std::vector<std::pair<double, std::string>> labels;
};

struct Description {
  std::string application;
  std::string backend;  // bridge, monitor
  std::uint32_t telemetry_period_us = 0;
  std::vector<Item> telemetry;
  std::vector<Item> parameters;
};

// Where a simulated plant takes disturbances (the plant-control endpoint of duet pil or duet plant serve).
struct PlantControlAddress {
  std::string host;
  std::uint16_t port = 0;
};

struct Backend {
  // Writes a parameter; the answer comes back through Dashboard::parameter (or client.error).
  std::function<void(Client& client, const std::string& name, double value)> set;
  std::function<void(Client& client)> describe;
  // The back end's part of the status message: `link`, `executive`, counters.
  std::function<nlohmann::json()> status;
  // Optional, for a server that speaks more than the dashboard (duet studio): what a client gets on joining before
  // the dashboard's welcome, and requests of other types (false: unknown, answered with an error).
  std::function<void(Client& client)> joined;
  std::function<bool(Client& client, const nlohmann::json& request)> request;
};

class PlantRelay;

class Dashboard {
 public:
  // With `plant_control`, the page's `plant` requests go to that endpoint, and while it is reachable the description
  // has a `plant` member saying what it offers (PlantRelay).
  Dashboard(boost::asio::io_context& io, ServerOptions options, Backend backend,
            std::optional<PlantControlAddress> plant_control = std::nullopt);
  ~Dashboard();
  Dashboard(const Dashboard&) = delete;
  Dashboard& operator=(const Dashboard&) = delete;

  Status start();  // listens, and sends status every second
  void close();
  [[nodiscard]] std::uint16_t port() const { return server_.port(); }

  void describe(Description description);
  void parameter(std::size_t index, std::optional<double> value, std::string_view status,
                 const std::string& problem = {});
  void telemetry(std::uint32_t sample, std::span<const double> values);
  // A block: `values` has one column per telemetry signal, each as long as `time_s`.
  void samples(std::span<const double> time_s, const std::vector<std::vector<double>>& values);
  void channel(bool open);
  void broadcast(const nlohmann::json& message, Delivery delivery);

  [[nodiscard]] std::uint64_t clients() const { return server_.clients(); }
  [[nodiscard]] std::uint64_t dropped_for_clients() const { return server_.dropped(); }
  [[nodiscard]] bool has_clients() const { return server_.has_clients(); }

 private:
  void welcome(Client& client);
  void publish_description();
  void handle(Client& client, const nlohmann::json& request);
  void record(Client& client, const nlohmann::json& request);
  void feed_recorder(double time_s, std::span<const double> values);
  // The `recorder` message of `state` with the armed settings.
  [[nodiscard]] Message recorder_message(Recorder::State state, const Description& description) const;
  void tick_status();
  [[nodiscard]] nlohmann::json status() const;
  // The MDF4 files (mdf4_downloads.cpp): GET recorder.mf4, the last capture; POST scope.mf4, the Scope's samples.
  // The description's `mdf4` member: where they are; null where they are not (no_mdf4_downloads.cpp).
  [[nodiscard]] nlohmann::json mdf4_offer() const;
  [[nodiscard]] std::optional<HttpAnswer> answer_http(const HttpRequest& request) const;
  [[nodiscard]] HttpAnswer recorder_file() const;
  [[nodiscard]] HttpAnswer scope_file(const std::string& body) const;

  // The last capture, with the signals it had when it was taken, for recorder.mf4.
  struct KeptCapture {
    Capture capture;
    std::vector<Item> telemetry;
    std::string application;
    std::int64_t completed_ns = 0;  // the back end's clock, ns since 1970
  };

  Backend backend_;
  Server server_;
  struct Timer;
  std::unique_ptr<Timer> status_timer_;
  std::optional<Description> description_;
  Message description_message_;
  std::vector<std::optional<double>> parameter_values_;
  Recorder recorder_;
  std::optional<KeptCapture> last_capture_;
  std::size_t max_upload_size_;
  std::unique_ptr<PlantRelay> plant_relay_;
};

}  // namespace duet::dashboard
