// The dashboard's MDF4 files (docs/DASHBOARD.md, "Saving as MDF4"): the recorder's last capture and the Scope's
// samples, written by src/mdf4 in the back end so that the page needs no MDF writer of its own.
#include <charconv>
#include <chrono>
#include <ctime>

#include "duet/dashboard/dashboard.hpp"
#include "measurement_file.hpp"
#include "scope_upload.hpp"

namespace duet::dashboard {
namespace {

constexpr std::string_view mdf4_type = "application/octet-stream";  // MDF has no registered media type

HttpAnswer text_answer(unsigned status, std::string text) {
  return {
      .status = status, .content_type = "text/plain; charset=utf-8", .body = std::move(text) + "\n", .attachment = {}};
}

// The fewest digits that read back as the same number.
std::string shortest(double value) {
  char text[32];
  const auto end = std::to_chars(std::begin(text), std::end(text), value).ptr;
  return {text, end};
}

// 2024-05-01T12-30-05 in UTC: sortable and valid in every file system, as the page's CSV names.
std::string timestamp_for_file(std::int64_t ns) {
  const std::time_t seconds = static_cast<std::time_t>(ns / 1'000'000'000);
  std::tm utc{};
  ::gmtime_r(&seconds, &utc);
  char text[32];
  const std::size_t length = std::strftime(text, sizeof text, "%Y-%m-%dT%H-%M-%S", &utc);
  return {text, length};
}

// A signal's name as part of a file name: letters, digits, '.', '-' and '_' only.
std::string file_name_part(std::string_view name) {
  std::string part{name};
  for (char& c : part) {
    const bool plain =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '-' || c == '_';
    if (!plain) c = '_';
  }
  return part;
}

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

HttpAnswer file_answer(const Measurement& measurement, std::string file_name) {
  auto bytes = mdf4_bytes(measurement);
  if (!bytes) return text_answer(500, "the MDF4 file could not be written: " + bytes.error());
  return {.status = 200,
          .content_type = std::string{mdf4_type},
          .body = std::move(bytes.value()),
          .attachment = std::move(file_name)};
}

}  // namespace

nlohmann::json Dashboard::mdf4_offer() const {
  return {{"recorder", "recorder.mf4"}, {"scope", "scope.mf4"}, {"max_request_bytes", max_upload_size_}};
}

std::optional<HttpAnswer> Dashboard::answer_http(const HttpRequest& request) const {
  const std::string_view path = std::string_view{request.target}.substr(0, request.target.find('?'));
  if (path == "/recorder.mf4") {
    if (request.method != "GET" && request.method != "HEAD") return text_answer(405, "recorder.mf4: GET it");
    return recorder_file();
  }
  if (path == "/scope.mf4") {
    if (request.method != "POST") return text_answer(405, "scope.mf4: POST the Scope's samples as JSON to it");
    return scope_file(request.body);
  }
  return std::nullopt;
}

HttpAnswer Dashboard::recorder_file() const {
  if (!last_capture_)
    return text_answer(404, "recorder.mf4: no capture yet: arm the recorder and wait for its trigger");
  const Capture& capture = last_capture_->capture;
  const TriggerSettings& settings = capture.settings;
  const std::vector<Item>& telemetry = last_capture_->telemetry;
  const std::string trigger_signal = settings.signal < telemetry.size() ? telemetry[settings.signal].name : "?";
  Measurement measurement{
      .group_name = "recorder",
      .group_comment = "trigger: " + trigger_signal + " " + std::string{name_of(settings.edge)} + " through " +
                       shortest(settings.level) + " at " + shortest(capture.trigger_time_s) + " s; pre-trigger " +
                       shortest(settings.pre_s) + " s, post-trigger " + shortest(settings.post_s) + " s",
      .file_comment = "duet dashboard: the recorder's capture of " + last_capture_->application,
      .start_time_ns = capture.time_s.empty() ? last_capture_->completed_ns
                                              : start_time_ns(capture.time_s.back(), last_capture_->completed_ns),
      .time_s = capture.time_s,
      .signals = {}};
  for (std::size_t index = 0; index < telemetry.size() && index < capture.values.size(); ++index) {
    const Item& item = telemetry[index];
    measurement.signals.push_back(
        {.name = item.name, .unit = item.unit, .described_type = item.type, .values = capture.values[index]});
  }
  return file_answer(measurement, "capture-" + file_name_part(trigger_signal) + "-" +
                                      timestamp_for_file(last_capture_->completed_ns) + ".mf4");
}

HttpAnswer Dashboard::scope_file(const std::string& body) const {
  auto measurement = scope_measurement(body, description_ ? description_->telemetry : std::vector<Item>{});
  if (!measurement) return text_answer(400, "scope.mf4: " + measurement.error());
  const std::int64_t now = now_ns();
  measurement.value().group_comment = "the Scope's samples as the page held them";
  measurement.value().file_comment =
      "duet dashboard: the Scope" + (description_ ? " of " + description_->application : std::string{});
  measurement.value().start_time_ns = start_time_ns(measurement.value().time_s.back(), now);
  return file_answer(measurement.value(), "scope-" + timestamp_for_file(now) + ".mf4");
}

}  // namespace duet::dashboard
