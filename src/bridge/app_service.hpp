#pragma once
// The application channel on the Linux side: reads the firmware's telemetry and parameter reports from the second
// inter-processor channel (/dev/ttyRPMSG1 on the board) and offers them to local clients
//   - to the dashboard (docs/DASHBOARD.md): its page over HTTP and, over WebSocket on the same port, JSON messages
//     (the description, samples, parameter reports, status, the recorder); clients set parameters by name;
//   - as CSV on standard output (a header from the description, then one line per sample), taking `name=value` lines
//     on standard input as parameter sets. A line that sets nothing (malformed, unknown, too long) is reported with
//     its number and counted, and the lines after it still count; CSV that cannot be written ends the service.
// The channel is retried when it goes away, and asked for its description whenever it (re)opens. Every queue is
// bounded: a client that does not keep up loses samples (counted), never parameter reports or answers.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "channel.hpp"
#include "duet/dashboard/dashboard.hpp"
#include "duet/support/result.hpp"

namespace duet::bridge {

struct AppServiceOptions {
  ChannelAddress channel;
  std::string channel_uri;  // as given, for messages
  std::string listen_address = "127.0.0.1";
  std::uint16_t websocket_port = 8765;  // 0: any free port
  bool websocket = true;
  std::filesystem::path web_root;  // the dashboard's files, served over HTTP on the WebSocket's port
  // A simulated plant's control endpoint (duet pil): the page may push and restart it. None on the board.
  std::optional<dashboard::PlantControlAddress> plant_control;
  bool csv = false;  // CSV on standard output, sets on standard input
  std::size_t channel_chunk = 496;
  // Extra status, as a JSON object's text, merged into status messages (the XCP relay's counters).
  std::function<std::string()> extra_status;
  bool verbose = false;
};

class AppService {
 public:
  explicit AppService(AppServiceOptions options);
  ~AppService();
  AppService(const AppService&) = delete;
  AppService& operator=(const AppService&) = delete;

  // Binds the WebSocket listener and tries the channel (a channel that is not there yet is retried).
  Status start();
  // Serves until stop(), from any thread, or until the CSV output fails (then the failure says why).
  Status run();
  void stop();

  [[nodiscard]] std::uint16_t websocket_port() const;
  // The counters as a JSON object's text; thread-safe.
  [[nodiscard]] std::string status() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace duet::bridge
