#pragma once
// duet studio's server (docs/STUDIO.md): one model file, its page over HTTP and the JSON protocol over WebSocket on
// one port (the dashboard's serving). It checks every text the page sends with the CLI's reader and checker, saves
// only over the version the page edited, tells the page when someone else changed the file, simulates and
// generates on request, and in external mode feeds the page from a target's XCP slave (the dashboard's monitor).
// It reads and writes only the model file and reads files beside it. Runs on the caller's io_context.

#include <boost/asio/io_context.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "duet/dashboard/server.hpp"
#include "duet/support/result.hpp"

namespace duet::studio {

struct StudioOptions {
  std::filesystem::path model;  // the model file
  dashboard::ServerOptions server;
  // The page's defaults: a plant (a name, or a plant model's file beside the model), a scenario file beside the
  // model, a duration, a target's XCP address (external mode connects at start when given).
  std::string plant = "none";
  std::string scenario;
  double duration_s = 5;
  std::string xcp;
  int timeout_ms = 1000;  // for each XCP command
};

class Studio {
 public:
  // Reads the model file; fails naming it when it cannot be read. A model that does not check is fine: the page
  // shows its errors.
  static Result<std::unique_ptr<Studio>> create(boost::asio::io_context& io, StudioOptions options);
  ~Studio();  // NOLINT(bugprone-exception-escape): joining threads throws only on a bug; ending then is right
  Studio(const Studio&) = delete;
  Studio& operator=(const Studio&) = delete;

  Status start();  // listens
  // Stops a running simulation and external mode; call once the io_context has stopped.
  void stop();
  [[nodiscard]] std::uint16_t port() const;

 private:
  class Impl;
  explicit Studio(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace duet::studio
