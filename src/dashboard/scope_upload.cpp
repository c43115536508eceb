#include "scope_upload.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace duet::dashboard {
namespace {

using nlohmann::json;

Status only_members(const json& object, const std::set<std::string>& allowed, const std::string& where) {
  for (const auto& [key, value] : object.items()) {
    if (!allowed.contains(key)) return Failure{where + " has a member '" + key + "' the scope's file does not take"};
  }
  return done();
}

Result<std::vector<double>> times_of(const json& request) {
  if (!request.contains("time_s") || !request["time_s"].is_array())
    return Failure{"\"time_s\" must be an array of the samples' times in seconds"};
  const json& times = request["time_s"];
  if (times.empty()) return Failure{"\"time_s\" is empty: there are no samples to save"};
  if (times.size() > ScopeLimits::max_samples)
    return Failure{"\"time_s\" has " + std::to_string(times.size()) + " samples, more than " +
                   std::to_string(ScopeLimits::max_samples)};
  std::vector<double> time_s;
  time_s.reserve(times.size());
  for (const json& time : times) {
    const std::string where = "\"time_s\"[" + std::to_string(time_s.size()) + "]";
    if (!time.is_number()) return Failure{where + " is not a number"};
    const double value = time.get<double>();
    if (!std::isfinite(value)) return Failure{where + " is not finite"};
    if (!time_s.empty() && value < time_s.back())
      return Failure{where + " (" + time.dump() + ") is before the time preceding it"};
    time_s.push_back(value);
  }
  return time_s;
}

Result<MeasuredSignal> signal_of(const json& signal, std::size_t index, std::size_t samples,
                                 const std::vector<Item>& telemetry) {
  const std::string where = "\"signals\"[" + std::to_string(index) + "]";
  if (!signal.is_object()) return Failure{where + " is not an object with name, unit and values"};
  if (Status members = only_members(signal, {"name", "unit", "values"}, where); !members)
    return Failure{members.error()};
  if (!signal.contains("name") || !signal["name"].is_string() || signal["name"].get<std::string>().empty())
    return Failure{where + " has no \"name\" (a non-empty string)"};
  MeasuredSignal measured{.name = signal["name"].get<std::string>(), .unit = {}, .described_type = {}, .values = {}};
  const std::string named = where + " ('" + measured.name + "')";
  if (signal.contains("unit")) {
    if (!signal["unit"].is_string()) return Failure{named + ": \"unit\" is not a string"};
    measured.unit = signal["unit"].get<std::string>();
  }
  if (!signal.contains("values") || !signal["values"].is_array())
    return Failure{named + " has no \"values\" (an array of numbers or null)"};
  const json& values = signal["values"];
  if (values.size() != samples)
    return Failure{named + " has " + std::to_string(values.size()) + " values for " + std::to_string(samples) +
                   " times"};
  measured.values.reserve(samples);
  for (const json& value : values) {
    if (value.is_null()) {
      measured.values.push_back(std::nan(""));
    } else if (value.is_number()) {
      measured.values.push_back(value.get<double>());
    } else {
      return Failure{named + ": value " + std::to_string(measured.values.size()) + " is neither a number nor null"};
    }
  }
  const auto described =
      std::find_if(telemetry.begin(), telemetry.end(), [&](const Item& item) { return item.name == measured.name; });
  if (described != telemetry.end()) measured.described_type = described->type;
  return measured;
}

}  // namespace

Result<Measurement> scope_measurement(std::string_view body, const std::vector<Item>& telemetry) {
  if (const auto numbers = static_cast<std::size_t>(std::count(body.begin(), body.end(), ','));
      numbers > ScopeLimits::max_numbers)
    return Failure{"the request holds more than " + std::to_string(ScopeLimits::max_numbers) + " numbers"};
  const json request = json::parse(body, nullptr, false);
  if (request.is_discarded()) return Failure{"the request is not JSON"};
  if (!request.is_object()) return Failure{"the request is not a JSON object with \"time_s\" and \"signals\""};
  if (Status members = only_members(request, {"time_s", "signals"}, "the request"); !members)
    return Failure{members.error()};
  auto time_s = times_of(request);
  if (!time_s) return Failure{time_s.error()};
  if (!request.contains("signals") || !request["signals"].is_array() || request["signals"].empty())
    return Failure{"\"signals\" must be a non-empty array of {name, unit, values}"};
  const json& signals = request["signals"];
  if (signals.size() > ScopeLimits::max_signals)
    return Failure{"\"signals\" has " + std::to_string(signals.size()) + " signals, more than " +
                   std::to_string(ScopeLimits::max_signals)};
  Measurement measurement{.group_name = "scope",
                          .group_comment = {},
                          .file_comment = {},
                          .start_time_ns = 0,
                          .time_s = std::move(time_s.value()),
                          .signals = {}};
  std::set<std::string> names;
  for (std::size_t index = 0; index < signals.size(); ++index) {
    auto signal = signal_of(signals[index], index, measurement.time_s.size(), telemetry);
    if (!signal) return Failure{signal.error()};
    if (!names.insert(signal.value().name).second)
      return Failure{"\"signals\"[" + std::to_string(index) + "]: '" + signal.value().name + "' is there twice"};
    measurement.signals.push_back(std::move(signal.value()));
  }
  return measurement;
}

}  // namespace duet::dashboard
