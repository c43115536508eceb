#pragma once
// The Linux or PC end of the application channel: learns the firmware's description, decodes its telemetry and
// parameter reports into named values, and encodes requests. Malformed input is counted and reported, never trusted.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "duet/app_channel/protocol.hpp"
#include "duet/support/result.hpp"
#include "duet/xcp/framing.hpp"

namespace duet::app_channel::host {

struct ItemDescription {
  std::string name;
  std::string unit;
  ValueType type = ValueType::f32;
  double minimum = 0;
  double maximum = 0;
  std::vector<std::string> labels;  // value k's name; empty: a number
};

struct Description {
  std::string application;
  std::uint32_t telemetry_period_us = 0;
  std::vector<ItemDescription> telemetry;
  std::vector<ItemDescription> parameters;
};

struct Sample {
  std::uint32_t sample = 0;
  std::vector<double> values;  // in the order of Description::telemetry
};

struct ParameterReport {
  std::size_t index = 0;
  ParameterStatus status = ParameterStatus::reported;
  std::optional<double> value;  // none when the index was unknown
};

struct TaskTiming {
  std::string name;
  std::uint32_t activations = 0;
  std::uint32_t overruns = 0;
  std::uint32_t min_cycles = 0;
  std::uint32_t mean_cycles = 0;
  std::uint32_t max_cycles = 0;
};

// The executive's account, whole: an `executive` packet and every `task` packet it announced.
struct ExecutiveReport {
  std::uint64_t ticks = 0;
  std::uint32_t base_period_ns = 0;
  std::uint32_t busy_ppm = 0;
  std::uint32_t overruns = 0;
  std::uint32_t cycle_hz = 0;
  std::vector<TaskTiming> tasks;
};

struct PeerCounters {
  std::uint64_t samples = 0;
  std::uint64_t frames_lost = 0;  // gaps in the firmware's frame counter
  std::uint64_t garbage_bytes = 0;
  std::uint64_t malformed_packets = 0;
};

class Peer {
 public:
  struct Handlers {
    std::function<void(const Description&)> description;
    std::function<void(const Sample&)> telemetry;
    std::function<void(const ParameterReport&)> parameter;
    std::function<void(const ExecutiveReport&)> executive;
    std::function<void(const std::string&)> problem;  // a malformed packet, named
  };

  explicit Peer(Handlers handlers);

  // Bytes from the firmware, in any pieces.
  void receive(std::span<const std::uint8_t> bytes);
  // Forgets a partial frame and the description (the channel was reopened: the firmware may have changed).
  void reset();

  [[nodiscard]] const std::optional<Description>& description() const { return description_; }
  // The last value reported for each parameter (none before the first report).
  [[nodiscard]] const std::vector<std::optional<double>>& parameter_values() const { return parameter_values_; }
  [[nodiscard]] PeerCounters counters() const;

  // The frame that asks the firmware for its description.
  [[nodiscard]] std::vector<std::uint8_t> describe_request();
  // The frame that sets parameter `name`; fails if there is no description yet, no such parameter, or the value is
  // not a number or outside the parameter's limits.
  [[nodiscard]] Result<std::vector<std::uint8_t>> set_request(std::string_view name, double value);

 private:
  void handle(std::span<const std::uint8_t> packet);
  void finish_executive();
  void problem(const std::string& what);

  Handlers handlers_;
  std::vector<std::uint8_t> decoder_buffer_;
  xcp::FrameDecoder decoder_;
  std::optional<Description> description_;
  std::optional<Description> incoming_;       // a description being received
  std::optional<ExecutiveReport> executive_;  // an account being received
  std::size_t executive_tasks_ = 0;           // of it so far
  std::vector<std::optional<double>> parameter_values_;
  std::optional<std::uint16_t> last_counter_;
  std::uint16_t request_counter_ = 0;
  PeerCounters counters_;
};

[[nodiscard]] std::string_view name_of(ValueType type);
[[nodiscard]] std::string_view name_of(ParameterStatus status);

}  // namespace duet::app_channel::host
