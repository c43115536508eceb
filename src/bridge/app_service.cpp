#include "app_service.hpp"

#include <boost/asio.hpp>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>

#include "duet/app_channel/host/peer.hpp"
#include "duet/dashboard/dashboard.hpp"
#include "duet/dashboard/executive_status.hpp"

namespace duet::bridge {

namespace asio = boost::asio;
using app_channel::host::Description;
using app_channel::host::ParameterReport;
using app_channel::host::Peer;
using app_channel::host::Sample;
using nlohmann::json;
using error_code = boost::system::error_code;

namespace {

constexpr std::size_t max_input_line = 4096;

dashboard::Item item_of(const app_channel::host::ItemDescription& item) {
  dashboard::Item described{item.name,    item.unit,    std::string{app_channel::host::name_of(item.type)},
                            item.minimum, item.maximum, {}};
  for (std::size_t value = 0; value < item.labels.size(); ++value) {
    described.labels.emplace_back(static_cast<double>(value), item.labels[value]);
  }
  return described;
}

}  // namespace

class AppService::Impl {
 public:
  explicit Impl(AppServiceOptions options)
      : options_(std::move(options)),
        retry_timer_(io_),
        channel_(io_),
        input_(io_),
        peer_({.description = [this](const Description& description) { on_description(description); },
               .telemetry = [this](const Sample& sample) { on_sample(sample); },
               .parameter = [this](const ParameterReport& report) { on_parameter(report); },
               .executive = [this](const app_channel::host::ExecutiveReport& report) { on_executive(report); },
               .problem = [this](const std::string& problem) { log("application channel: " + problem); }}) {
    if (options_.websocket) {
      dashboard_.emplace(io_,
                         dashboard::ServerOptions{.address = options_.listen_address,
                                                  .port = options_.websocket_port,
                                                  .web_root = options_.web_root,
                                                  .log_name = "duet-bridge"},
                         dashboard::Backend{.set = [this](dashboard::Client& client, const std::string& name,
                                                          double value) { set(client, name, value); },
                                            .describe = [this](dashboard::Client& client) { describe(client); },
                                            .status = [this] { return status_json(); }},
                         options_.plant_control);
    }
  }

  Status start() {
    if (dashboard_) {
      if (Status started = dashboard_->start(); !started) return Failure{"dashboard: " + started.error()};
    }
    open_channel();
    return done();
  }

  Status run() {
    io_.run();
    if (csv_failure_) return Failure{*csv_failure_};
    return done();
  }
  void stop() {
    asio::post(io_, [this] { io_.stop(); });
  }

  [[nodiscard]] std::uint16_t port() const { return dashboard_ ? dashboard_->port() : 0; }

  // Thread-safe: reads atomics only (and the relay's counters through extra_status).
  [[nodiscard]] json status_json() const {
    json status = {{"link", {{"state", channel_open_ ? "open" : "closed"}, {"address", options_.channel_uri}}},
                   {"application_channel",
                    {{"open", channel_open_.load()},
                     {"opens", channel_opens_.load()},
                     {"samples", samples_.load()},
                     {"frames_lost", frames_lost_.load()},
                     {"garbage_bytes", garbage_bytes_.load()},
                     {"malformed_packets", malformed_.load()},
                     {"input_lines_rejected", input_lines_rejected_.load()},
                     {"clients", dashboard_ ? dashboard_->clients() : 0},
                     {"samples_dropped_for_clients", dashboard_ ? dashboard_->dropped_for_clients() : 0}}}};
    {
      const std::lock_guard lock{executive_mutex_};
      if (!executive_.is_null()) status["executive"] = executive_;
    }
    if (options_.extra_status) {
      json extra = json::parse(options_.extra_status(), nullptr, false);
      if (extra.is_object()) status.update(extra);
    }
    return status;
  }

 private:
  void log(const std::string& line) const { std::cerr << "duet-bridge: " << line << std::endl; }

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
    retry_timer_.async_wait([this](error_code error) {
      if (!error && !channel_.is_open()) open_channel();
      if (!error && channel_.is_open() && !to_channel_.empty() && !writing_channel_) write_channel();
    });
  }

  void close_channel(const std::string& reason) {
    if (!channel_.is_open()) return;
    error_code ignored;
    channel_.close(ignored);
    channel_open_ = false;
    writing_channel_ = false;
    to_channel_.clear();
    log("application channel " + options_.channel_uri + " closed (" + reason + "); retrying");
    {
      const std::lock_guard lock{executive_mutex_};
      executive_ = nullptr;
    }
    if (dashboard_) dashboard_->channel(false);
    retry_in(retry_delay_);
  }

  void read_channel() {
    channel_.async_read_some(asio::buffer(read_buffer_), [this](error_code error, std::size_t received) {
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
    channel_.async_write_some(asio::buffer(to_channel_.data(), chunk), [this](error_code error, std::size_t written) {
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

  void set(dashboard::Client& client, const std::string& name, double value) {
    if (!channel_.is_open()) return client.error("the application channel is not open");
    auto frame = peer_.set_request(name, value);
    if (!frame) return client.error(frame.error());
    send_to_channel(frame.value());
  }

  void describe(dashboard::Client& client) {
    if (!channel_.is_open()) return client.error("the application channel is not open");
    send_to_channel(peer_.describe_request());
  }

  void on_description(const Description& description) {
    if (dashboard_) {
      dashboard::Description described{description.application, "bridge", description.telemetry_period_us, {}, {}};
      for (const auto& item : description.telemetry) described.telemetry.push_back(item_of(item));
      for (const auto& item : description.parameters) described.parameters.push_back(item_of(item));
      dashboard_->describe(std::move(described));
    }
    if (options_.verbose) {
      log("application " + description.application + ": " + std::to_string(description.telemetry.size()) +
          " telemetry signals, " + std::to_string(description.parameters.size()) + " parameters");
    }
    if (options_.csv) {
      std::string header = "sample";
      for (const auto& item : description.telemetry) {
        header += "," + item.name + (item.unit.empty() ? "" : " [" + item.unit + "]");
      }
      if (header != csv_header_) write_csv(header);  // a repeated description: no new header
      csv_header_ = header;
      if (!reading_input_) read_input();
    }
  }

  void on_sample(const Sample& sample) {
    ++samples_;
    if (dashboard_) dashboard_->telemetry(sample.sample, sample.values);
    if (options_.csv) {
      std::ostringstream line;
      line.precision(9);  // a float's every digit
      line << sample.sample;
      for (const double value : sample.values) line << ',' << value;
      write_csv(line.str());
    }
  }

  // CSV nobody can read is data lost without a word: the service stops and says why (standard output closed by its
  // reader, a full disk).
  void write_csv(const std::string& line) {
    if (csv_failure_) return;
    std::cout << line << '\n' << std::flush;
    if (std::cout) return;
    csv_failure_ = "CSV output on standard output: " + std::string{std::strerror(errno)};
    io_.stop();
  }

  void on_parameter(const ParameterReport& report) {
    const std::string_view status = app_channel::host::name_of(report.status);
    if (dashboard_) dashboard_->parameter(report.index, report.value, status);
    const auto& description = peer_.description();
    if (options_.csv && report.status != app_channel::ParameterStatus::reported && description &&
        report.index < description->parameters.size()) {
      log("parameter " + description->parameters[report.index].name + " = " +
          (report.value ? json(*report.value).dump() : "?") + " (" + std::string{status} + ")");
    }
  }

  // The dashboard's Status page shows the last account.
  void on_executive(const app_channel::host::ExecutiveReport& report) {
    json executive = dashboard::executive_status(report);
    const std::lock_guard lock{executive_mutex_};
    executive_ = std::move(executive);
  }

  // `name=value` lines on standard input set parameters (CSV mode, for scripts).
  // Only once the application has described itself: before, no line could name a parameter.
  void read_input() {
    reading_input_ = true;
    error_code error;
    input_.assign(::dup(STDIN_FILENO), error);
    if (error) return;  // no standard input (closed): no sets from it
    read_input_line();
  }
  void read_input_line() {
    asio::async_read_until(input_, asio::dynamic_buffer(input_line_, max_input_line), '\n',
                           [this](error_code error, std::size_t length) {
                             ++input_line_number_;
                             if (error == asio::error::not_found) {  // no newline in max_input_line bytes
                               reject_input_line("longer than " + std::to_string(max_input_line) + " bytes");
                               input_line_.clear();
                               return skip_rest_of_line();
                             }
                             if (error) {  // a last line without a newline still counts
                               if (!input_line_.empty()) set_from_line(input_line_);
                               if (error != asio::error::eof)
                                 log("standard input: " + error.message() + "; not read further");
                               return;
                             }
                             std::string line = input_line_.substr(0, length - 1);
                             input_line_.erase(0, length);
                             set_from_line(line);
                             read_input_line();
                           });
  }
  void skip_rest_of_line() {
    asio::async_read_until(input_, asio::dynamic_buffer(input_line_, max_input_line), '\n',
                           [this](error_code error, std::size_t length) {
                             if (error == asio::error::not_found) {
                               input_line_.clear();
                               return skip_rest_of_line();
                             }
                             if (error) return;  // end of input
                             input_line_.erase(0, length);
                             read_input_line();
                           });
  }
  void set_from_line(const std::string& line) {
    const std::size_t equals = line.find('=');
    if (line.empty()) return;
    double value = 0;
    std::istringstream number{equals == std::string::npos ? std::string{} : line.substr(equals + 1)};
    if (equals == std::string::npos || !(number >> value))
      return reject_input_line("'" + line + "': expected name=value");
    if (!channel_.is_open()) return reject_input_line("the application channel is not open");
    auto request = peer_.set_request(line.substr(0, equals), value);
    if (!request) return reject_input_line(request.error());
    send_to_channel(request.value());
  }
  void reject_input_line(const std::string& problem) {
    ++input_lines_rejected_;
    log("standard input line " + std::to_string(input_line_number_) + ": " + problem + "; ignored");
  }

  AppServiceOptions options_;
  asio::io_context io_;
  asio::steady_timer retry_timer_;
  asio::posix::stream_descriptor channel_;
  asio::posix::stream_descriptor input_;
  std::string input_line_;
  bool reading_input_ = false;
  std::uint64_t input_line_number_ = 0;
  std::optional<std::string> csv_failure_;
  std::array<std::uint8_t, 4096> read_buffer_{};
  std::vector<std::uint8_t> to_channel_;
  bool writing_channel_ = false;
  bool channel_failing_ = false;
  std::chrono::milliseconds retry_delay_{100};
  Peer peer_;
  std::optional<dashboard::Dashboard> dashboard_;
  std::string csv_header_;

  mutable std::mutex executive_mutex_;
  json executive_;  // the last account, for status (read from other threads too)

  std::atomic<bool> channel_open_{false};
  std::atomic<std::uint64_t> channel_opens_{0}, samples_{0}, frames_lost_{0}, garbage_bytes_{0}, malformed_{0},
      input_lines_rejected_{0};
};

AppService::AppService(AppServiceOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}
AppService::~AppService() = default;
Status AppService::start() { return impl_->start(); }
Status AppService::run() { return impl_->run(); }
void AppService::stop() { impl_->stop(); }
std::uint16_t AppService::websocket_port() const { return impl_->port(); }
std::string AppService::status() const {
  json status = impl_->status_json();
  status["type"] = "status";
  return status.dump();
}

}  // namespace duet::bridge
