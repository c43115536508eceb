#pragma once
// The dashboard's recorder: a triggered capture evaluated on every sample the target took (DAQ or the application's
// telemetry), never on a polled value. Armed with a signal, a level and an edge, it keeps the last `pre_s` seconds;
// when the signal crosses the level it goes on for `post_s` seconds and hands over the capture. Bounded: a capture
// holds at most `max_samples` samples (settings that would need more are refused).

#include <cstddef>
#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::dashboard {

enum class Edge { rising, falling, either };

struct TriggerSettings {
  std::size_t signal = 0;  // index into each sample's values
  double level = 0;
  Edge edge = Edge::rising;
  double pre_s = 0;
  double post_s = 1;
};

struct Capture {
  TriggerSettings settings;
  double trigger_time_s = 0;
  std::vector<double> time_s;
  std::vector<std::vector<double>> values;  // per signal, as long as time_s
};

class Recorder {
 public:
  static constexpr std::size_t max_samples = 200'000;

  enum class State { idle, armed, triggered };

  // `sample_period_s` (the fastest the target samples) bounds the capture's length; `signals` values per sample.
  // Fails, naming the setting, when the signal does not exist, a time is negative or the capture would be too long.
  Status arm(const TriggerSettings& settings, std::size_t signals, double sample_period_s);
  void cancel();
  // One sample; a capture when this sample completed one (the recorder is then idle again).
  std::optional<Capture> take(double time_s, std::span<const double> values);

  [[nodiscard]] State state() const { return state_; }
  [[nodiscard]] const TriggerSettings& settings() const { return settings_; }

 private:
  struct Sample {
    double time_s;
    std::vector<double> values;
  };
  [[nodiscard]] bool crosses(double before, double now) const;
  Capture finish();

  State state_ = State::idle;
  TriggerSettings settings_;
  std::deque<Sample> samples_;
  std::optional<double> previous_;
  double trigger_time_s_ = 0;
};

std::string_view name_of(Edge edge);
std::optional<Edge> edge_named(std::string_view name);
std::string_view name_of(Recorder::State state);

}  // namespace duet::dashboard
