#pragma once
// duet monitor's back end: the dashboard fed by duet's XCP master (docs/DASHBOARD.md). A thread of its own owns
// the master, because its commands block: it connects (and reconnects when the target goes away), reads every
// parameter, samples the chosen signals with DAQ on one event and hands them to the dashboard in blocks every
// 20 ms; a `set` becomes a DOWNLOAD, read back with an UPLOAD. The dashboard runs on the io_context's thread; the
// two meet through asio::post and a queue of writes. It serves a dashboard of its own, or feeds one its owner serves
// (duet studio's external mode), whose back end then calls set, describe and status.

#include <boost/asio/io_context.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "duet/dashboard/dashboard.hpp"
#include "duet/support/result.hpp"
#include "duet/xcp/host/a2l.hpp"
#include "duet/xcp/host/endpoint.hpp"

namespace duet::monitor {

struct MonitorOptions {
  xcp::host::Endpoint target;
  xcp::host::A2lDescription a2l;
  std::vector<std::string> signals;           // MEASUREMENT names (arrays as a whole); empty: every measurement
  std::string event;                          // name or number; empty: the fastest periodic event
  dashboard::ServerOptions server;            // its own dashboard's, when `dashboard` is none
  dashboard::Dashboard* dashboard = nullptr;  // the owner's, which must outlive the monitor
  // For its own dashboard: a simulated plant's control endpoint, so that the page may push and restart it.
  std::optional<dashboard::PlantControlAddress> plant_control;
  int timeout_ms = 1000;
};

class MonitorTarget {
 public:
  // Checks the options against the A2L (signals, event): failures name the option.
  static Result<std::unique_ptr<MonitorTarget>> create(boost::asio::io_context& io, MonitorOptions options);
  ~MonitorTarget();
  MonitorTarget(const MonitorTarget&) = delete;
  MonitorTarget& operator=(const MonitorTarget&) = delete;

  // Listens and starts talking to the target on a thread of its own.
  Status start();
  // Stops the thread (stopping DAQ and disconnecting) and the listener; call once the io_context has stopped.
  void stop();
  [[nodiscard]] std::uint16_t port() const;

  // The dashboard back end's parts, on the io_context's thread (status: any thread).
  void set(dashboard::Client& client, const std::string& name, double value);
  void describe();
  [[nodiscard]] nlohmann::json status() const;

 private:
  class Impl;
  explicit MonitorTarget(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace duet::monitor
