#include "duet/dashboard/dashboard.hpp"

#include <boost/asio.hpp>

#include <algorithm>
#include <chrono>

#include "plant_relay.hpp"

namespace duet::dashboard {

using nlohmann::json;

struct Dashboard::Timer {
  explicit Timer(boost::asio::io_context& io) : timer(io) {}
  boost::asio::steady_timer timer;
};

namespace {

json item_json(const Item& item) {
  json described = {
      {"name", item.name}, {"unit", item.unit}, {"type", item.type}, {"min", item.minimum}, {"max", item.maximum}};
  if (!item.labels.empty()) {
    json labels = json::array();
    for (const auto& [value, text] : item.labels) labels.push_back({{"value", value}, {"text", text}});
    described["labels"] = std::move(labels);
  }
  return described;
}

json recorder_json(Recorder::State state, const TriggerSettings& settings, const Description& description) {
  json message = {{"type", "recorder"}, {"state", name_of(state)}};
  if (state != Recorder::State::idle && settings.signal < description.telemetry.size()) {
    message.update({{"signal", description.telemetry[settings.signal].name},
                    {"level", settings.level},
                    {"edge", name_of(settings.edge)},
                    {"pre_s", settings.pre_s},
                    {"post_s", settings.post_s}});
  }
  return message;
}

// A number member, or `otherwise` when absent; nullopt when present but not a number.
std::optional<double> number_member(const json& object, const char* name, double otherwise) {
  if (!object.contains(name)) return otherwise;
  if (!object[name].is_number()) return std::nullopt;
  return object[name].get<double>();
}

}  // namespace

Dashboard::Dashboard(boost::asio::io_context& io, ServerOptions options, Backend backend,
                     std::optional<PlantControlAddress> plant_control)
    : backend_(std::move(backend)),
      server_(io, options,
              ServerHandlers{.joined = [this](Client& client) { welcome(client); },
                             .request = [this](Client& client, const json& request) { handle(client, request); },
                             .http = [this](const HttpRequest& request) { return answer_http(request); }}),
      status_timer_(std::make_unique<Timer>(io)),
      max_upload_size_(options.max_upload_size) {
  if (plant_control) {
    plant_relay_ = std::make_unique<PlantRelay>(
        io, std::move(*plant_control),
        PlantRelay::Handlers{
            .described = [this] { publish_description(); },
            .applied = [this](const json& event) { server_.broadcast(dashboard::message(event), Delivery::always); }});
  }
}

Dashboard::~Dashboard() = default;

Status Dashboard::start() {
  if (Status started = server_.start(); !started) return started;
  tick_status();
  if (plant_relay_) plant_relay_->start();
  return done();
}

void Dashboard::close() {
  server_.close();
  status_timer_->timer.cancel();
  if (plant_relay_) plant_relay_->close();
}

void Dashboard::describe(Description description) {
  parameter_values_.assign(description.parameters.size(), std::nullopt);
  if (recorder_.state() != Recorder::State::idle) {
    recorder_.cancel();  // its signal index may mean another signal now
    server_.broadcast(recorder_message(recorder_.state(), description), Delivery::always);
  }
  description_ = std::move(description);
  publish_description();
}

// The target's description, with what the plant behind it offers while its endpoint is reachable.
void Dashboard::publish_description() {
  if (!description_) return;
  const Description& description = *description_;
  json message = {{"type", "description"},          {"application", description.application},
                  {"backend", description.backend}, {"telemetry_period_us", description.telemetry_period_us},
                  {"telemetry", json::array()},     {"parameters", json::array()}};
  for (const Item& item : description.telemetry) message["telemetry"].push_back(item_json(item));
  for (const Item& item : description.parameters) message["parameters"].push_back(item_json(item));
  if (plant_relay_ && plant_relay_->description()) message["plant"] = *plant_relay_->description();
  if (json offer = mdf4_offer(); !offer.is_null()) message["mdf4"] = std::move(offer);
  description_message_ = dashboard::message(message);
  server_.broadcast(description_message_, Delivery::always);
}

void Dashboard::parameter(std::size_t index, std::optional<double> value, std::string_view status,
                          const std::string& problem) {
  json message = {{"type", "parameter"}, {"index", index}, {"status", status}};
  if (value) message["value"] = *value;
  if (!problem.empty()) message["message"] = problem;
  if (description_ && index < description_->parameters.size()) {
    message["name"] = description_->parameters[index].name;
    if (value) parameter_values_[index] = value;
  }
  server_.broadcast(dashboard::message(message), Delivery::always);
}

void Dashboard::telemetry(std::uint32_t sample, std::span<const double> values) {
  if (server_.has_clients()) {
    server_.broadcast(dashboard::message({{"type", "telemetry"}, {"sample", sample}, {"values", values}}),
                      Delivery::droppable);
  }
  if (description_) feed_recorder(sample * (description_->telemetry_period_us * 1e-6), values);
}

void Dashboard::samples(std::span<const double> time_s, const std::vector<std::vector<double>>& values) {
  if (server_.has_clients()) {
    server_.broadcast(dashboard::message({{"type", "samples"}, {"time_s", time_s}, {"values", values}}),
                      Delivery::droppable);
  }
  if (recorder_.state() == Recorder::State::idle) return;
  std::vector<double> row(values.size());
  for (std::size_t k = 0; k < time_s.size(); ++k) {
    for (std::size_t signal = 0; signal < values.size(); ++signal)
      row[signal] = k < values[signal].size() ? values[signal][k] : 0.0;
    feed_recorder(time_s[k], row);
  }
}

Message Dashboard::recorder_message(Recorder::State state, const Description& description) const {
  return dashboard::message(recorder_json(state, recorder_.settings(), description));
}

void Dashboard::channel(bool open) {
  server_.broadcast(dashboard::message({{"type", "channel"}, {"open", open}}), Delivery::always);
}

void Dashboard::feed_recorder(double time_s, std::span<const double> values) {
  const Recorder::State before = recorder_.state();
  auto capture = recorder_.take(time_s, values);
  if (!description_) return;
  if (before == Recorder::State::armed && recorder_.state() != Recorder::State::armed) {  // triggered just now
    server_.broadcast(recorder_message(Recorder::State::triggered, *description_), Delivery::always);
  }
  if (!capture) return;
  const Item& signal = description_->telemetry[capture->settings.signal];
  server_.broadcast(dashboard::message({{"type", "capture"},
                                        {"signal", signal.name},
                                        {"level", capture->settings.level},
                                        {"edge", name_of(capture->settings.edge)},
                                        {"trigger_time_s", capture->trigger_time_s},
                                        {"time_s", capture->time_s},
                                        {"values", capture->values}}),
                    Delivery::always);
  server_.broadcast(recorder_message(recorder_.state(), *description_), Delivery::always);
  if (mdf4_offer().is_null()) return;  // nobody will ask for it
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  last_capture_ = KeptCapture{.capture = std::move(*capture),
                              .telemetry = description_->telemetry,
                              .application = description_->application,
                              .completed_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(now).count()};
}

void Dashboard::broadcast(const json& message, Delivery delivery) {
  server_.broadcast(dashboard::message(message), delivery);
}

void Dashboard::welcome(Client& client) {
  if (backend_.joined) backend_.joined(client);
  if (!description_message_) return;
  client.send(description_message_, Delivery::always);
  for (std::size_t index = 0; index < parameter_values_.size(); ++index) {
    if (!parameter_values_[index]) continue;
    client.send(dashboard::message({{"type", "parameter"},
                                    {"index", index},
                                    {"name", description_->parameters[index].name},
                                    {"value", *parameter_values_[index]},
                                    {"status", "reported"}}),
                Delivery::always);
  }
  if (recorder_.state() != Recorder::State::idle)
    client.send(recorder_message(recorder_.state(), *description_), Delivery::always);
}

void Dashboard::handle(Client& client, const json& request) {
  const std::string type = request["type"].get<std::string>();
  if (type == "status") return client.send(dashboard::message(status()), Delivery::always);
  if (type == "describe") return backend_.describe(client);
  if (type == "set") {
    if (!request.contains("name") || !request["name"].is_string() || !request.contains("value") ||
        !request["value"].is_number()) {
      return client.error("set needs \"name\" (a string) and \"value\" (a number)");
    }
    return backend_.set(client, request["name"].get<std::string>(), request["value"].get<double>());
  }
  if (type == "record") return record(client, request);
  if (type == "plant") {
    if (plant_relay_) return plant_relay_->request(client, request);
    return client.send(dashboard::message({{"type", "plant"},
                                           {"error", "no simulated plant behind this target (no --plant-control)"}}),
                       Delivery::always);
  }
  if (type == "cancel_record") {
    recorder_.cancel();
    if (description_) server_.broadcast(recorder_message(recorder_.state(), *description_), Delivery::always);
    return;
  }
  if (backend_.request && backend_.request(client, request)) return;
  client.error("unknown request type '" + type + "': set, describe, status, record, cancel_record or plant");
}

void Dashboard::record(Client& client, const json& request) {
  if (!description_) return client.error("record: the target has not described itself yet");
  if (!request.contains("signal") || !request["signal"].is_string())
    return client.error("record needs \"signal\": the name of a telemetry signal");
  const std::string name = request["signal"].get<std::string>();
  const auto& telemetry = description_->telemetry;
  const auto found =
      std::find_if(telemetry.begin(), telemetry.end(), [&](const Item& item) { return item.name == name; });
  if (found == telemetry.end()) return client.error("record: '" + name + "' is no telemetry signal");
  const auto level = number_member(request, "level", 0);
  const auto pre_s = number_member(request, "pre_s", 0);
  const auto post_s = number_member(request, "post_s", 1);
  if (!level || !pre_s || !post_s) return client.error("record: level, pre_s and post_s are numbers");
  const std::string edge_name = request.contains("edge") && request["edge"].is_string()
                                    ? request["edge"].get<std::string>()
                                    : std::string{"rising"};
  const auto edge = edge_named(edge_name);
  if (!edge) return client.error("record: edge '" + edge_name + "' is not rising, falling or either");
  const TriggerSettings settings{.signal = static_cast<std::size_t>(found - telemetry.begin()),
                                 .level = *level,
                                 .edge = *edge,
                                 .pre_s = *pre_s,
                                 .post_s = *post_s};
  const double period_s = std::max(description_->telemetry_period_us, 1U) * 1e-6;
  if (Status armed = recorder_.arm(settings, telemetry.size(), period_s); !armed) return client.error(armed.error());
  server_.broadcast(recorder_message(recorder_.state(), *description_), Delivery::always);
}

json Dashboard::status() const {
  json message = backend_.status ? backend_.status() : json::object();
  message["type"] = "status";
  message["dashboard"] = {{"clients", server_.clients()},
                          {"messages_dropped_for_clients", server_.dropped()},
                          {"files_served", server_.files_served()}};
  if (plant_relay_) message["plant"] = plant_relay_->status();
  return message;
}

void Dashboard::tick_status() {
  status_timer_->timer.expires_after(std::chrono::seconds{1});
  status_timer_->timer.async_wait([this](const boost::system::error_code& error) {
    if (error) return;
    if (server_.has_clients()) server_.broadcast(dashboard::message(status()), Delivery::droppable);
    tick_status();
  });
}

}  // namespace duet::dashboard
