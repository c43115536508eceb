#include "duet/studio/studio.hpp"

#include <boost/asio.hpp>
#include <nlohmann/json.hpp>

#include <fstream>
#include <optional>

#include "duet/dashboard/dashboard.hpp"
#include "duet/model/generate.hpp"
#include "duet/model/task_set_file.hpp"
#include "duet/monitor/monitor_target.hpp"
#include "duet/plant/plant.hpp"
#include "duet/studio/generation.hpp"
#include "duet/studio/library.hpp"
#include "duet/studio/model_view.hpp"
#include "duet/studio/simulation_job.hpp"
#include "duet/support/content_hash.hpp"
#include "duet/support/text_file.hpp"
#include "duet/xcp/host/a2l.hpp"

namespace duet::studio {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr std::size_t max_request_bytes = 1 << 20;  // a model's text fits many times over

std::optional<std::string> string_member(const json& request, const char* name) {
  if (!request.contains(name) || !request[name].is_string()) return std::nullopt;
  return request[name].get<std::string>();
}

// task -> microseconds, from a request's object of numbers; malformed entries are the request's error.
Result<std::map<std::string, double>> times_member(const json& request, const char* name) {
  std::map<std::string, double> times;
  if (!request.contains(name)) return times;
  if (!request[name].is_object()) return Failure{std::string{name} + " is an object of task: microseconds"};
  for (const auto& [task, value] : request[name].items()) {
    if (!value.is_number() || !(value.get<double>() > 0))
      return Failure{std::string{name} + "." + task + " is not a positive number"};
    times[task] = value.get<double>();
  }
  return times;
}

}  // namespace

class Studio::Impl {
 public:
  Impl(boost::asio::io_context& io, StudioOptions options)
      : io_(io), options_(std::move(options)), folder_(options_.model.parent_path()), file_timer_(io) {
    if (folder_.empty()) folder_ = ".";
  }

  Status read_model() {
    auto text = read_text_file(options_.model.string());
    if (!text) return Failure{text.error()};
    disk_version_ = content_hash(text.value());
    disk_text_ = std::move(text).value();
    return done();
  }

  Status start() {
    dashboard::ServerOptions server = options_.server;
    server.index = "studio.html";
    server.max_request_size = max_request_bytes;
    dashboard_.emplace(io_, server,
                       dashboard::Backend{.set = [this](dashboard::Client& client, const std::string& name,
                                                        double value) { set(client, name, value); },
                                          .describe =
                                              [this](dashboard::Client&) {
                                                if (monitor_) monitor_->describe();
                                              },
                                          .status = [this] { return status(); },
                                          .joined = [this](dashboard::Client& client) { welcome(client); },
                                          .request = [this](dashboard::Client& client,
                                                            const json& request) { return handle(client, request); }});
    if (Status started = dashboard_->start(); !started) return started;
    watch_file();
    if (!options_.xcp.empty()) connect(options_.xcp, nullptr);
    return done();
  }

  void stop() {
    simulation_.reset();
    if (monitor_) monitor_->stop();
    monitor_.reset();
    file_timer_.cancel();
    if (dashboard_) dashboard_->close();
  }

  [[nodiscard]] std::uint16_t port() const { return dashboard_ ? dashboard_->port() : 0; }

 private:
  void welcome(dashboard::Client& client) {
    json plants = json::array();
    for (const std::string& name : plant::plant_names()) plants.push_back({{"name", name}, {"description", ""}});
    client.send(dashboard::message({{"type", "studio"},
                                    {"file", options_.model.filename().string()},
                                    {"version", disk_version_},
                                    {"text", disk_text_},
                                    {"library", library_},
                                    {"plants", std::move(plants)},
                                    {"files", files_beside()},
                                    {"defaults",
                                     {{"plant", options_.plant},
                                      {"scenario", options_.scenario},
                                      {"duration_s", options_.duration_s},
                                      {"xcp", options_.xcp}}}}),
                dashboard::Delivery::always);
    send_model(client, disk_text_, 0);
    client.send(dashboard::message(external_message()), dashboard::Delivery::always);
  }

  bool handle(dashboard::Client& client, const json& request) {
    const std::string type = request["type"].get<std::string>();
    if (type == "check") {
      const auto text = string_member(request, "text");
      if (!text) return reply_error(client, type, "check needs \"text\": the model's text");
      const json seq = request.contains("seq") ? request["seq"] : json(0);
      send_model(client, *text, seq);
      return true;
    }
    if (type == "save") return save(client, request);
    if (type == "reload") {
      if (Status read = read_model(); !read) return reply_error(client, type, read.error());
      client.send(dashboard::message({{"type", "file"}, {"text", disk_text_}, {"version", disk_version_}}),
                  dashboard::Delivery::always);
      return true;
    }
    if (type == "simulate") return simulate(client, request);
    if (type == "cancel_simulation") {
      if (simulation_) simulation_->cancel();
      return true;
    }
    if (type == "generate") return generate(client, request);
    if (type == "connect") {
      const auto address = string_member(request, "address");
      if (!address) return reply_error(client, type, "connect needs \"address\": tcp://HOST:PORT or udp://HOST:PORT");
      connect(*address, &client);
      return true;
    }
    if (type == "disconnect") {
      disconnect();
      return true;
    }
    return false;
  }

  bool reply_error(dashboard::Client& client, const std::string& request, const std::string& text) {
    client.send(dashboard::message({{"type", "error"}, {"request", request}, {"message", text}}),
                dashboard::Delivery::always);
    return true;
  }

  void send_model(dashboard::Client& client, const std::string& text, const json& seq) {
    const CheckedText checked = check_text(text, options_.model.string());
    json message = model_view(checked, text);
    message["type"] = "model";
    message["seq"] = seq;
    client.send(dashboard::message(message), dashboard::Delivery::always);
    if (checked.program) last_good_text_ = text;
  }

  // Only over the version the page edited: a file changed by someone else is never overwritten.
  bool save(dashboard::Client& client, const json& request) {
    const auto text = string_member(request, "text");
    const auto base = string_member(request, "base");
    if (!text || !base) return reply_error(client, "save", R"(save needs "text" and "base" (the version edited))");
    auto on_disk = read_text_file(options_.model.string());
    const std::string disk_version = on_disk ? content_hash(on_disk.value()) : std::string{};
    if (!on_disk || disk_version != *base) {
      client.send(dashboard::message({{"type", "save_refused"},
                                      {"reason", on_disk ? "the file changed on disk since it was opened"
                                                         : "the file cannot be read: " + on_disk.error()},
                                      {"version", disk_version}}),
                  dashboard::Delivery::always);
      return true;
    }
    const fs::path temporary = options_.model.string() + ".duet-saving";
    {
      std::ofstream file{temporary, std::ios::binary | std::ios::trunc};
      file << *text;
      if (!file.flush()) return reply_error(client, "save", "cannot write " + temporary.string());
    }
    std::error_code error;
    fs::rename(temporary, options_.model, error);
    if (error) return reply_error(client, "save", "cannot replace " + options_.model.string() + ": " + error.message());
    disk_text_ = *text;
    disk_version_ = content_hash(disk_text_);
    client.send(dashboard::message({{"type", "saved"}, {"version", disk_version_}}), dashboard::Delivery::always);
    return true;
  }

  // Once a second: has someone else changed the file?
  void watch_file() {
    file_timer_.expires_after(std::chrono::seconds{1});
    file_timer_.async_wait([this](const boost::system::error_code& error) {
      if (error) return;
      auto text = read_text_file(options_.model.string());
      if (text) {
        const std::string version = content_hash(text.value());
        if (version != disk_version_ && version != announced_version_) {
          announced_version_ = version;
          dashboard_->broadcast({{"type", "file_changed"}, {"version", version}}, dashboard::Delivery::always);
        }
      }
      report_external_state();
      watch_file();
    });
  }

  // A file beside the model (in its folder or below), by its path from there, or one the command line named: nothing
  // else on the machine is reachable by a request.
  Result<std::string> beside(const std::string& name, const std::string& what) const {
    if (!name.empty() && (name == options_.plant || name == options_.scenario)) return name;
    const fs::path relative{name};
    bool plain = !name.empty() && relative.is_relative();
    for (const fs::path& part : relative) plain = plain && !part.empty() && !part.string().starts_with('.');
    if (!plain) return Failure{what + " '" + name + "' is not the name of a file beside the model"};
    const fs::path path = folder_ / relative;
    if (!fs::is_regular_file(path)) return Failure{what + " '" + name + "' is not a file beside the model"};
    return path.string();
  }

  // The YAML files beside the model and in its subfolders (a plant model, the robot's scenarios), by their paths
  // from the model's folder.
  [[nodiscard]] json files_beside() const {
    std::vector<std::string> names;
    std::error_code error;
    for (fs::recursive_directory_iterator entry{folder_, error}, end; !error && entry != end; entry.increment(error)) {
      const fs::path relative = entry->path().lexically_relative(folder_);
      const bool hidden = entry->path().filename().string().starts_with('.');
      if (entry->is_directory()) {
        if (hidden || entry.depth() >= 1) entry.disable_recursion_pending();  // one level down, no further
        continue;
      }
      if (!hidden && entry->is_regular_file() && relative.extension() == ".yaml" &&
          relative != options_.model.filename())
        names.push_back(relative.string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  bool simulate(dashboard::Client& client, const json& request) {
    const auto text = string_member(request, "text");
    if (!text) return reply_error(client, "simulate", "simulate needs \"text\": the model's text");
    SimulationRequest job{*text, options_.model.string(), options_.plant,
                          {},    options_.duration_s,     request.contains("id") ? request["id"] : json(0)};
    if (const auto plant = string_member(request, "plant"); plant && !plant->empty()) {
      job.plant = *plant;
      if (plant->ends_with(".yaml")) {
        auto path = beside(*plant, "plant");
        if (!path) return reply_error(client, "simulate", path.error());
        job.plant = path.value();
      }
    }
    if (const auto scenario = string_member(request, "scenario"); scenario && !scenario->empty()) {
      auto path = beside(*scenario, "scenario");
      if (!path) return reply_error(client, "simulate", path.error());
      job.scenario = path.value();
    }
    if (request.contains("duration_s")) {
      if (!request["duration_s"].is_number()) return reply_error(client, "simulate", "duration_s is a number");
      job.duration_s = request["duration_s"].get<double>();
    }
    simulation_.reset();  // one at a time: a new request replaces (cancels) the running one
    const json id = job.id;
    simulation_ = std::make_unique<SimulationJob>(
        std::move(job),
        [this, id](double fraction) {
          boost::asio::post(io_, [this, id, fraction] {
            dashboard_->broadcast({{"type", "simulation_progress"}, {"id", id}, {"fraction", fraction}},
                                  dashboard::Delivery::droppable);
          });
        },
        [this](json message) {
          boost::asio::post(io_, [this, message = std::move(message)] {
            dashboard_->broadcast(message, dashboard::Delivery::always);
          });
        });
    return true;
  }

  bool generate(dashboard::Client& client, const json& request) {
    const auto text = string_member(request, "text");
    if (!text) return reply_error(client, "generate", "generate needs \"text\": the model's text");
    const CheckedText checked = check_text(*text, options_.model.string());
    if (!checked.program) return reply_error(client, "generate", "generate: the model has errors: fix them first");
    auto wcet = times_member(request, "wcet_us");
    auto interarrival = times_member(request, "interarrival_us");
    if (!wcet) return reply_error(client, "generate", wcet.error());
    if (!interarrival) return reply_error(client, "generate", interarrival.error());
    TaskTimes times{std::move(wcet).value(), std::move(interarrival).value()};
    add_measured_times(*checked.program, times);
    auto message = generated_message(checked, options_.model.filename().string(), times);
    if (!message) return reply_error(client, "generate", "generate: " + message.error());
    client.send(dashboard::message(message.value()), dashboard::Delivery::always);
    return true;
  }

  // A connected target's longest measured execution times stand in for those the page did not give.
  void add_measured_times(const model::Program& program, TaskTimes& times) const {
    if (!monitor_) return;
    const json status = monitor_->status();
    if (!status.contains("executive")) return;
    for (const model::ProgramTask& task : program.tasks) {
      const std::string account_name = model::account_task_name(task);
      for (const json& measured : status["executive"]["tasks"]) {
        if (measured["name"] == account_name && measured["max_us"].get<double>() > 0)
          times.wcet_us.try_emplace(model::task_function_name(task), measured["max_us"].get<double>());
      }
    }
  }

  // External mode: the model's A2L (generated from the last text that checked) tells the monitor where everything
  // is; it samples every measurable signal by DAQ and feeds this server's dashboard.
  void connect(const std::string& address, dashboard::Client* client) {
    disconnect();
    auto failed = [&](const std::string& problem) {
      external_problem_ = problem;
      dashboard_->broadcast(external_message(), dashboard::Delivery::always);
      if (client != nullptr) reply_error(*client, "connect", "connect: " + problem);
    };
    auto endpoint = xcp::host::parse_endpoint(address);
    if (!endpoint) return failed(endpoint.error());
    // Before any page checked a text (--xcp at start), the file's.
    const CheckedText checked =
        check_text(last_good_text_.empty() ? disk_text_ : last_good_text_, options_.model.string());
    if (!checked.program) return failed("the model has errors: its A2L cannot be generated");
    auto files = model::generate(*checked.program, options_.model.filename().string());
    if (!files) return failed(files.error());
    const auto a2l_file = std::find_if(files.value().begin(), files.value().end(),
                                       [](const model::GeneratedFile& file) { return file.name.ends_with(".a2l"); });
    auto a2l = xcp::host::read_a2l(a2l_file->text, a2l_file->name);
    if (!a2l) return failed(a2l.error());
    auto monitor = monitor::MonitorTarget::create(io_, {.target = endpoint.value(),
                                                        .a2l = std::move(a2l).value(),
                                                        .dashboard = &*dashboard_,
                                                        .timeout_ms = options_.timeout_ms});
    if (!monitor) return failed(monitor.error());
    if (Status started = monitor.value()->start(); !started) return failed(started.error());
    monitor_ = std::shared_ptr<monitor::MonitorTarget>{std::move(monitor).value()};
    external_address_ = address;
    external_problem_.clear();
    dashboard_->broadcast(external_message(), dashboard::Delivery::always);
  }

  // Joins the monitor's thread (at most one XCP timeout); what it posted before runs before it is destroyed.
  void disconnect() {
    if (!monitor_) return;
    monitor_->stop();
    boost::asio::post(io_, [retired = std::move(monitor_)] {});
    monitor_.reset();
    dashboard_->channel(false);
    dashboard_->broadcast(external_message(), dashboard::Delivery::always);
  }

  // The monitor's link (its state, and the last attempt's problem), or "off" with the last connect's problem.
  [[nodiscard]] json external_message() const {
    json message = {{"type", "external"}, {"state", "off"}, {"address", external_address_}};
    if (monitor_) {
      const json link = monitor_->status()["link"];
      message["state"] = link["state"];
      if (link.contains("problem")) message["problem"] = link["problem"];
    } else if (!external_problem_.empty()) {
      message["problem"] = external_problem_;
    }
    return message;
  }

  void report_external_state() {
    json message = external_message();
    if (message["state"] == reported_state_) return;
    reported_state_ = message["state"].get<std::string>();
    dashboard_->broadcast(message, dashboard::Delivery::always);
  }

  [[nodiscard]] json status() const {
    json status = monitor_ ? monitor_->status() : json::object();
    status["external"] = {{"state", monitor_ ? status["link"]["state"] : json("off")}, {"address", external_address_}};
    return status;
  }

  void set(dashboard::Client& client, const std::string& name, double value) {
    if (!monitor_) return client.error("set " + name + ": not connected to a target (connect first)");
    monitor_->set(client, name, value);
  }

  boost::asio::io_context& io_;
  StudioOptions options_;
  fs::path folder_;
  boost::asio::steady_timer file_timer_;
  std::optional<dashboard::Dashboard> dashboard_;
  const json library_ = library_json();  // the same for every page that joins
  std::string disk_text_;
  std::string disk_version_;
  std::string announced_version_;  // the last foreign version the page was told of
  std::string last_good_text_;     // the last text a page had checked that checked, for external mode's A2L
  std::unique_ptr<SimulationJob> simulation_;
  std::shared_ptr<monitor::MonitorTarget> monitor_;
  std::string external_address_;
  std::string external_problem_;
  std::string reported_state_ = "off";
};

Result<std::unique_ptr<Studio>> Studio::create(boost::asio::io_context& io, StudioOptions options) {
  auto impl = std::make_unique<Impl>(io, std::move(options));
  if (Status read = impl->read_model(); !read) return Failure{read.error()};
  return std::unique_ptr<Studio>{new Studio{std::move(impl)}};
}

Studio::Studio(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Studio::~Studio() { impl_->stop(); }
Status Studio::start() { return impl_->start(); }
void Studio::stop() { impl_->stop(); }
std::uint16_t Studio::port() const { return impl_->port(); }

}  // namespace duet::studio
