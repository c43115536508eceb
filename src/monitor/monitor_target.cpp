#include "duet/monitor/monitor_target.hpp"

#include <boost/asio.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <span>
#include <thread>

#include "duet/dashboard/dashboard.hpp"
#include "duet/model/generate.hpp"
#include "duet/monitor/executive_account_layout.hpp"
#include "duet/xcp/host/epk.hpp"
#include "duet/xcp/host/master.hpp"
#include "duet/xcp/host/values.hpp"

namespace duet::monitor {
namespace {

using namespace duet::xcp::host;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

constexpr auto block_period = std::chrono::milliseconds{20};
constexpr auto daq_wait = std::chrono::milliseconds{5};
constexpr auto longest_retry = std::chrono::milliseconds{2000};
constexpr auto account_period = std::chrono::seconds{1};

// One element of a MEASUREMENT or CHARACTERISTIC: arrays show as NAME[0], NAME[1], ...
struct Element {
  const Variable* variable = nullptr;
  std::uint32_t index = 0;
  [[nodiscard]] std::string name() const {
    return variable->count > 1 ? variable->name + "[" + std::to_string(index) + "]" : variable->name;
  }
  [[nodiscard]] std::uint32_t address() const {
    return variable->address + index * static_cast<std::uint32_t>(size_of(variable->type));
  }
  [[nodiscard]] std::size_t size() const { return size_of(variable->type); }
  // The physical value of this element's bytes.
  [[nodiscard]] double decode(std::span<const std::uint8_t> bytes) const {
    Variable scalar = *variable;
    scalar.count = 1;
    return xcp::host::decode(scalar, bytes).front();
  }
};

std::string type_name(DataType type) {
  static constexpr const char* names[] = {"uint8", "int8",   "uint16", "int16",   "uint32",
                                          "int32", "uint64", "int64",  "float32", "float64"};
  return names[static_cast<std::size_t>(type)];
}

dashboard::Item item_of(const Element& element) {
  dashboard::Item described{element.name(),
                            element.variable->unit,
                            type_name(element.variable->type),
                            element.variable->minimum,
                            element.variable->maximum,
                            {}};
  for (const xcp::host::Label& label : element.variable->labels) described.labels.emplace_back(label.raw, label.text);
  return described;
}

std::vector<Element> elements_of(const Variable& variable) {
  std::vector<Element> elements;
  for (std::uint32_t index = 0; index < variable.count; ++index) elements.push_back({&variable, index});
  return elements;
}

}  // namespace

class MonitorTarget::Impl {
 public:
  Impl(boost::asio::io_context& io, MonitorOptions options) : io_(io), options_(std::move(options)) {}

  Status choose() {
    const A2lDescription& a2l = options_.a2l;
    if (options_.signals.empty()) {  // every signal of the model; the executive's account is the Status page's
      for (const Variable& variable : a2l.measurements) {
        if (!model::is_executive_account(a2l, variable)) options_.signals.push_back(variable.name);
      }
    }
    account_ = ExecutiveAccountLayout::from(a2l);
    for (const std::string& name : options_.signals) {
      const auto found = std::find_if(a2l.measurements.begin(), a2l.measurements.end(),
                                      [&](const Variable& variable) { return variable.name == name; });
      if (found == a2l.measurements.end())
        return Failure{"--signal " + name + ": no MEASUREMENT of that name in the A2L"};
      for (const Element& element : elements_of(*found)) signals_.push_back(element);
    }
    for (const Variable& variable : a2l.characteristics) {
      for (const Element& element : elements_of(variable)) parameters_.push_back(element);
    }
    parameter_values_.assign(parameters_.size(), std::nullopt);
    for (const EventInfo& info : a2l.events) {
      if (info.time_cycle != 0 && (base_period_s_ == 0 || info.period_s() < base_period_s_))
        base_period_s_ = info.period_s();
      if (options_.event.empty() ? info.time_cycle != 0 && (!event_ || info.period_s() < event_->period_s())
                                 : info.name == options_.event || std::to_string(info.channel) == options_.event)
        event_ = info;
    }
    if (!event_ && !options_.event.empty()) return Failure{"--event " + options_.event + ": no such event in the A2L"};
    if (!event_ && !signals_.empty())
      return Failure{"the A2L has no periodic event to sample the signals on: give --event"};
    return done();
  }

  Status start() {
    dashboard_ = options_.dashboard;
    if (dashboard_ == nullptr) {
      own_dashboard_.emplace(io_, options_.server,
                             dashboard::Backend{.set = [this](dashboard::Client& client, const std::string& name,
                                                              double value) { set(client, name, value); },
                                                .describe = [this](dashboard::Client&) { describe(); },
                                                .status = [this] { return status(); }},
                             options_.plant_control);
      if (Status started = own_dashboard_->start(); !started) return started;
      dashboard_ = &*own_dashboard_;
    }
    describe();
    worker_ = std::thread{[this] { work(); }};
    return done();
  }

  void stop() {
    {
      const std::lock_guard lock{mutex_};
      stopping_ = true;
    }
    wake_.notify_all();
    if (worker_.joinable()) worker_.join();
    if (own_dashboard_) own_dashboard_->close();
  }

  [[nodiscard]] std::uint16_t port() const { return dashboard_ != nullptr ? dashboard_->port() : 0; }

  // On the io thread.
  void describe() {
    dashboard::Description description{options_.a2l.module.empty() ? options_.a2l.project : options_.a2l.module,
                                       "monitor",
                                       event_ ? static_cast<std::uint32_t>(event_->period_s() * 1e6 + 0.5) : 0,
                                       {},
                                       {}};
    for (const Element& element : signals_) description.telemetry.push_back(item_of(element));
    for (const Element& element : parameters_) description.parameters.push_back(item_of(element));
    dashboard_->describe(std::move(description));
    for (std::size_t index = 0; index < parameter_values_.size(); ++index) {
      if (parameter_values_[index]) dashboard_->parameter(index, parameter_values_[index], "reported");
    }
  }

  void set(dashboard::Client& client, const std::string& name, double value) {
    const auto found = std::find_if(parameters_.begin(), parameters_.end(),
                                    [&](const Element& element) { return element.name() == name; });
    if (found == parameters_.end()) return client.error("set: '" + name + "' is no parameter (CHARACTERISTIC)");
    // A write kept for a target that is not there would land, unasked, whenever it comes back.
    if (link_state_ != LinkState::open) return client.error("set " + name + ": the target is not connected");
    auto bytes = encode(*found->variable, value);
    if (!bytes) return client.error("set " + name + ": " + bytes.error());
    {
      const std::lock_guard lock{mutex_};
      writes_.push_back({static_cast<std::size_t>(found - parameters_.begin()), std::move(bytes).value()});
    }
    wake_.notify_all();
  }

  // Thread-safe.
  [[nodiscard]] json status() const {
    json link = {{"state", link_state_name()}, {"address", to_string(options_.target)}};
    {
      const std::lock_guard lock{mutex_};
      if (!link_problem_.empty()) link["problem"] = link_problem_;
    }
    json status = {{"link", link},
                   {"xcp",
                    {{"event", event_ ? event_->name : ""},
                     {"signals", signals_.size()},
                     {"connects", connects_.load()},
                     {"samples", samples_.load()},
                     {"packets_lost", packets_lost_.load()},
                     {"overloads", overloads_.load()},
                     {"writes", writes_done_.load()},
                     {"writes_failed", writes_failed_.load()}}}};
    const std::lock_guard lock{mutex_};
    if (!account_json_.is_null()) status["executive"] = account_json_;
    return status;
  }

 private:
  struct Write {
    std::size_t parameter = 0;
    std::vector<std::uint8_t> bytes;
  };

  enum class LinkState { connecting, open, closed };
  [[nodiscard]] std::string link_state_name() const {
    switch (link_state_.load()) {
      case LinkState::connecting: return "connecting";
      case LinkState::open: return "open";
      case LinkState::closed: return "closed";
    }
    return "?";
  }

  // On the worker thread from here on.
  void work() {
    auto retry = std::chrono::milliseconds{100};
    while (!stopping()) {
      link_state_ = LinkState::connecting;
      Status session = serve_session();
      if (stopping()) break;
      {
        const std::lock_guard lock{mutex_};
        link_problem_ = session ? std::string{} : session.error();
      }
      link_state_ = LinkState::closed;
      post([this] { dashboard_->channel(false); });
      std::unique_lock lock{mutex_};
      wake_.wait_for(lock, retry, [this] { return stopping_; });
      retry = std::min(retry * 2, longest_retry);
    }
  }

  // One connection to the target, until it fails or the monitor stops.
  Status serve_session() {
    const std::chrono::milliseconds timeout{options_.timeout_ms};
    auto channel = MasterChannel::open(options_.target, timeout);
    if (!channel) return Failure{channel.error()};
    Master master{std::move(channel).value(), timeout};
    if (auto connected = master.connect(); !connected) return Failure{connected.error()};
    if (Status same = check_epk(master, options_.a2l); !same) return same;
    ++connects_;
    {
      const std::lock_guard lock{mutex_};
      link_problem_.clear();
    }
    for (std::size_t index = 0; index < parameters_.size(); ++index) {
      auto value = read(master, index);
      if (!value) return Failure{value.error()};
      post([this, index, value = value.value()] { report(index, value, "reported"); });
    }
    if (!signals_.empty()) {
      DaqListSetup list{.event = event_->channel, .prescaler = 1};
      for (const Element& element : signals_)
        list.entries.push_back(
            {element.variable->extension, element.address(), static_cast<std::uint8_t>(element.size())});
      if (Status started = master.start_daq({list}); !started) return started;
    }
    link_state_ = LinkState::open;
    post([this] { describe(); });
    Status ended = sample(master);
    (void)master.stop_daq();
    (void)master.disconnect();
    return ended;
  }

  Status sample(Master& master) {
    // The slave's timestamps, counted on across their wraps by the master; a slave without them gets the event's
    // period per sample.
    const double tick_s = master.seconds_per_tick();
    std::uint64_t count = 0;
    const double event_s = event_ ? event_->period_s() : 0.0;
    std::vector<double> times;
    std::vector<std::vector<double>> columns(signals_.size());
    auto block_started = Clock::now();
    auto account_due = Clock::now();
    while (!stopping()) {
      if (Status written = write_pending(master); !written) return written;
      if (account_ && Clock::now() >= account_due) {
        if (Status read = read_account(master); !read) return read;
        account_due += account_period;
      }
      auto received = master.receive_samples(signals_.empty() ? std::chrono::milliseconds{50} : daq_wait);
      if (!received) return Failure{received.error()};
      for (const DaqSample& sample : received.value()) {
        times.push_back(tick_s > 0 ? static_cast<double>(sample.ticks) * tick_s : static_cast<double>(count) * event_s);
        ++count;
        std::size_t at = 0;
        for (std::size_t signal = 0; signal < signals_.size(); ++signal) {
          const Element& element = signals_[signal];
          columns[signal].push_back(at + element.size() <= sample.bytes.size()
                                        ? element.decode(std::span{sample.bytes}.subspan(at, element.size()))
                                        : 0.0);
          at += element.size();
        }
      }
      samples_ += received.value().size();
      const PacketCounters counters = master.counters();
      packets_lost_ = counters.lost() - counters.overload_events;  // lost on the way, or unusable
      overloads_ = counters.overload_events;
      if (!times.empty() && Clock::now() - block_started >= block_period) {
        post([this, times = std::move(times), columns = std::move(columns)] { dashboard_->samples(times, columns); });
        times = {};
        columns = std::vector<std::vector<double>>(signals_.size());
        block_started = Clock::now();
      } else if (times.empty()) {
        block_started = Clock::now();
      }
    }
    return done();
  }

  Status write_pending(Master& master) {
    for (;;) {
      Write write;
      {
        const std::lock_guard lock{mutex_};
        if (writes_.empty()) return done();
        write = std::move(writes_.front());
        writes_.pop_front();
      }
      const Element& element = parameters_[write.parameter];
      if (Status written = master.download(element.variable->extension, element.address(), write.bytes); !written) {
        ++writes_failed_;
        post([this, index = write.parameter, problem = written.error()] {
          report(index, std::nullopt, "failed", problem);
        });
        if (written.error().find("ERR_") == std::string::npos) return written;  // no answer: the link is gone
        continue;
      }
      auto value = read(master, write.parameter);
      if (!value) return Failure{value.error()};
      ++writes_done_;
      post([this, index = write.parameter, value = value.value()] { report(index, value, "applied"); });
    }
  }

  // The executive's account, for the Status page. A target that refuses it (firmware that keeps none) is asked no
  // more; no answer means the link is gone.
  Status read_account(Master& master) {
    const xcp::host::MemoryInfo& segment = account_->segment();
    auto bytes = master.upload(segment.extension, segment.address, segment.size);
    if (!bytes) {
      if (bytes.error().find("ERR_") == std::string::npos) return Failure{bytes.error()};
      account_.reset();
      return done();
    }
    json account = account_->decode(bytes.value(), static_cast<std::uint32_t>(std::llround(base_period_s_ * 1e9)));
    const std::lock_guard lock{mutex_};
    account_json_ = std::move(account);
    return done();
  }

  Result<double> read(Master& master, std::size_t parameter) {
    const Element& element = parameters_[parameter];
    auto bytes =
        master.upload(element.variable->extension, element.address(), static_cast<std::uint32_t>(element.size()));
    if (!bytes) return Failure{bytes.error()};
    return element.decode(bytes.value());
  }

  // On the io thread.
  void report(std::size_t index, std::optional<double> value, std::string_view status,
              const std::string& problem = {}) {
    if (value) parameter_values_[index] = value;
    dashboard_->parameter(index, value, status, problem);
  }

  template <typename Work>
  void post(Work work) {
    boost::asio::post(io_, std::move(work));
  }

  bool stopping() {
    const std::lock_guard lock{mutex_};
    return stopping_;
  }

  boost::asio::io_context& io_;
  MonitorOptions options_;
  std::vector<Element> signals_;
  std::vector<Element> parameters_;
  std::optional<EventInfo> event_;
  std::optional<ExecutiveAccountLayout> account_;  // read by the worker only, after choose()
  double base_period_s_ = 0;                       // the fastest periodic event's
  std::optional<dashboard::Dashboard> own_dashboard_;
  dashboard::Dashboard* dashboard_ = nullptr;            // the own one or the owner's
  std::vector<std::optional<double>> parameter_values_;  // on the io thread
  std::thread worker_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::deque<Write> writes_;
  std::string link_problem_;
  json account_json_;  // the last account read

  std::atomic<LinkState> link_state_{LinkState::connecting};
  std::atomic<std::uint64_t> connects_{0}, samples_{0}, packets_lost_{0}, overloads_{0}, writes_done_{0},
      writes_failed_{0};
};

Result<std::unique_ptr<MonitorTarget>> MonitorTarget::create(boost::asio::io_context& io, MonitorOptions options) {
  auto impl = std::make_unique<Impl>(io, std::move(options));
  if (Status chosen = impl->choose(); !chosen) return Failure{chosen.error()};
  return std::unique_ptr<MonitorTarget>{new MonitorTarget{std::move(impl)}};
}

MonitorTarget::MonitorTarget(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
MonitorTarget::~MonitorTarget() { impl_->stop(); }
Status MonitorTarget::start() { return impl_->start(); }
void MonitorTarget::stop() { impl_->stop(); }
std::uint16_t MonitorTarget::port() const { return impl_->port(); }
void MonitorTarget::set(dashboard::Client& client, const std::string& name, double value) {
  impl_->set(client, name, value);
}
void MonitorTarget::describe() { impl_->describe(); }
nlohmann::json MonitorTarget::status() const { return impl_->status(); }

}  // namespace duet::monitor
