#include "duet/dashboard/recorder.hpp"

#include <cmath>

namespace duet::dashboard {

Status Recorder::arm(const TriggerSettings& settings, std::size_t signals, double sample_period_s) {
  if (settings.signal >= signals) return Failure{"record: no signal " + std::to_string(settings.signal)};
  if (!std::isfinite(settings.level)) return Failure{"record: the level is not a number"};
  if (!(settings.pre_s >= 0) || !(settings.post_s >= 0) || !std::isfinite(settings.pre_s + settings.post_s)) {
    return Failure{"record: pre_s and post_s are seconds, 0 or more"};
  }
  const double samples = (settings.pre_s + settings.post_s) / sample_period_s;
  if (!(samples <= static_cast<double>(max_samples))) {
    return Failure{"record: " + std::to_string(settings.pre_s + settings.post_s) + " s are more than " +
                   std::to_string(max_samples) + " samples"};
  }
  settings_ = settings;
  state_ = State::armed;
  samples_.clear();
  previous_.reset();
  return done();
}

void Recorder::cancel() {
  state_ = State::idle;
  samples_.clear();
  previous_.reset();
}

bool Recorder::crosses(double before, double now) const {
  const bool rising = before < settings_.level && now >= settings_.level;
  const bool falling = before > settings_.level && now <= settings_.level;
  switch (settings_.edge) {
    case Edge::rising: return rising;
    case Edge::falling: return falling;
    case Edge::either: return rising || falling;
  }
  return false;
}

std::optional<Capture> Recorder::take(double time_s, std::span<const double> values) {
  if (state_ == State::idle || settings_.signal >= values.size()) return std::nullopt;
  samples_.push_back({time_s, {values.begin(), values.end()}});
  const double now = values[settings_.signal];
  if (state_ == State::armed) {
    // Only the pre-trigger time is kept while waiting (a sample on its boundary stays, whatever the rounding of the
    // times), and never more samples than a capture may hold.
    const double oldest_kept_s = time_s - settings_.pre_s - 1e-9;
    while (samples_.size() > max_samples || samples_.front().time_s < oldest_kept_s) samples_.pop_front();
    if (previous_ && crosses(*previous_, now)) {
      state_ = State::triggered;
      trigger_time_s_ = time_s;
    }
    previous_ = now;
  }
  if (state_ == State::triggered && (time_s >= trigger_time_s_ + settings_.post_s || samples_.size() >= max_samples))
    return finish();
  return std::nullopt;
}

Capture Recorder::finish() {
  Capture capture{settings_, trigger_time_s_, {}, {}};
  const std::size_t signals = samples_.empty() ? 0 : samples_.front().values.size();
  capture.values.resize(signals);
  capture.time_s.reserve(samples_.size());
  for (auto& column : capture.values) column.reserve(samples_.size());
  for (const Sample& sample : samples_) {
    capture.time_s.push_back(sample.time_s);
    for (std::size_t signal = 0; signal < signals && signal < sample.values.size(); ++signal)
      capture.values[signal].push_back(sample.values[signal]);
  }
  cancel();
  return capture;
}

std::string_view name_of(Edge edge) {
  switch (edge) {
    case Edge::rising: return "rising";
    case Edge::falling: return "falling";
    case Edge::either: return "either";
  }
  return "?";
}

std::optional<Edge> edge_named(std::string_view name) {
  for (const Edge edge : {Edge::rising, Edge::falling, Edge::either}) {
    if (name_of(edge) == name) return edge;
  }
  return std::nullopt;
}

std::string_view name_of(Recorder::State state) {
  switch (state) {
    case Recorder::State::idle: return "idle";
    case Recorder::State::armed: return "armed";
    case Recorder::State::triggered: return "triggered";
  }
  return "?";
}

}  // namespace duet::dashboard
