#include "duet/plant/balbot/balbot_scenario.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include "duet/support/closest_word.hpp"
#include "duet/support/text_file.hpp"

namespace duet::plant {
namespace {

constexpr double unbounded = std::numeric_limits<double>::infinity();

// The size of a pulse: a push's force or a disturbance's duty.
double& magnitude(BalbotPush& push) { return push.force_n; }
double& magnitude(BalbotDutyDisturbance& pulse) { return pulse.duty; }

using Problem = std::optional<Failure>;  // nothing when all is well

// Reads one file; each problem is "file:line: what". The readers store what they read in their last argument.
class ScenarioReader {
 public:
  explicit ScenarioReader(std::string file) : file_(std::move(file)) {}

  [[nodiscard]] Failure at(const YAML::Node& node, const std::string& what) const {
    return Failure{file_ + ":" + std::to_string(node.Mark().line + 1) + ": " + what};
  }

  // Every key of the map `node` is one of `known`.
  [[nodiscard]] Problem only(const YAML::Node& node, const std::string& where,
                             std::span<const std::string_view> known) const {
    for (const auto& entry : node) {
      const std::string key = entry.first.Scalar();
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      std::string what = where;
      what.append("unknown key '").append(key).append("'");
      if (const auto closest = closest_word(key, known)) {
        what.append(" (did you mean '").append(*closest).append("'?)");
      } else {
        what += " (known: ";
        for (std::size_t i = 0; i < known.size(); ++i) what.append(i == 0 ? "" : ", ").append(known[i]);
        what += ")";
      }
      return at(entry.first, what);
    }
    return std::nullopt;
  }

  // A number in [low, high].
  [[nodiscard]] Problem number(const YAML::Node& node, const std::string& name, double low, double high,
                               double& out) const {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !std::isfinite(value)) {
      return at(node, name + ": expected a number, got " + shown(node));
    }
    if (value < low || value > high) {
      return at(node, name + ": " + node.Scalar() + " is outside " + bound(low) + ".." + bound(high));
    }
    out = value;
    return std::nullopt;
  }

  [[nodiscard]] Problem boolean(const YAML::Node& node, const std::string& name, bool& out) const {
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, out)) {
      return at(node, name + ": expected true or false, got " + shown(node));
    }
    return std::nullopt;
  }

  [[nodiscard]] Problem whole(const YAML::Node& node, const std::string& name, std::uint64_t most,
                              std::uint64_t& out) const {
    std::uint64_t value = 0;
    const bool negative = node.IsScalar() && !node.Scalar().empty() && node.Scalar()[0] == '-';
    if (!node.IsScalar() || negative || !YAML::convert<std::uint64_t>::decode(node, value)) {
      return at(node, name + ": expected a whole number 0.." + std::to_string(most) + ", got " + shown(node));
    }
    if (value > most) return at(node, name + ": " + node.Scalar() + " is more than " + std::to_string(most));
    out = value;
    return std::nullopt;
  }

  // A map's required field.
  [[nodiscard]] Problem field(const YAML::Node& map, const std::string& where, const char* key, YAML::Node& out) const {
    const YAML::Node found = map[key];
    if (!found) return at(map, where + "'" + key + "' is missing");
    out.reset(found);  // rebinds `out` (its operator= would assign to the node it refers to)
    return std::nullopt;
  }

 private:
  static std::string shown(const YAML::Node& node) {
    if (node.IsScalar()) return "'" + node.Scalar() + "'";
    if (node.IsSequence()) return "a list";
    if (node.IsMap()) return "a map";
    return "nothing";
  }
  static std::string bound(double value) {
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    std::string text = std::to_string(value);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text;
  }

  std::string file_;
};

// Each entry of a list of maps, read by `entry(map, "where: ")`.
Problem each(const ScenarioReader& reader, const YAML::Node& node, const std::string& name,
             std::span<const std::string_view> keys,
             const std::function<Problem(const YAML::Node&, const std::string&)>& entry) {
  if (!node.IsSequence()) return reader.at(node, name + ": expected a list");
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node item = node[i];
    const std::string where = name + "[" + std::to_string(i) + "]: ";
    if (!item.IsMap()) return reader.at(item, where + "expected a map");
    if (Problem problem = reader.only(item, where, keys)) return problem;
    if (Problem problem = entry(item, where)) return problem;
  }
  return std::nullopt;
}

// time_s, a value, duration_s: a push or a disturbance.
template <typename Pulse>
Problem pulses(const ScenarioReader& reader, const YAML::Node& node, const std::string& name, const char* value_key,
               double low, double high, std::vector<Pulse>& out) {
  const std::array<std::string_view, 3> keys{"time_s", value_key, "duration_s"};
  return each(reader, node, name, keys, [&](const YAML::Node& item, const std::string& where) -> Problem {
    YAML::Node time;
    YAML::Node value;
    YAML::Node duration;
    Pulse pulse;
    if (Problem problem = reader.field(item, where, "time_s", time)) return problem;
    if (Problem problem = reader.field(item, where, value_key, value)) return problem;
    if (Problem problem = reader.field(item, where, "duration_s", duration)) return problem;
    if (Problem problem = reader.number(time, where + "time_s", 0, unbounded, pulse.time_s)) return problem;
    if (Problem problem = reader.number(value, where + value_key, low, high, magnitude(pulse))) return problem;
    if (Problem problem = reader.number(duration, where + "duration_s", 0, unbounded, pulse.duration_s)) {
      return problem;
    }
    out.push_back(pulse);
    return std::nullopt;
  });
}

Problem messages(const ScenarioReader& reader, const YAML::Node& node, std::vector<BalbotIpcMessage>& out) {
  const std::array<std::string_view, 2> keys{"time_s", "bytes"};
  return each(reader, node, "ipc_messages", keys, [&](const YAML::Node& item, const std::string& where) -> Problem {
    YAML::Node time;
    YAML::Node bytes;
    BalbotIpcMessage message;
    if (Problem problem = reader.field(item, where, "time_s", time)) return problem;
    if (Problem problem = reader.field(item, where, "bytes", bytes)) return problem;
    if (Problem problem = reader.number(time, where + "time_s", 0, unbounded, message.time_s)) return problem;
    if (!bytes.IsSequence()) return reader.at(bytes, where + "bytes: expected a list of numbers 0..255");
    if (bytes.size() > 496) {
      return reader.at(
          bytes, where + "bytes: " + std::to_string(bytes.size()) + " bytes are more than one message holds (496)");
    }
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      std::uint64_t byte = 0;
      if (Problem problem = reader.whole(bytes[i], where + "bytes[" + std::to_string(i) + "]", 255, byte)) {
        return problem;
      }
      message.bytes.push_back(static_cast<std::uint8_t>(byte));
    }
    out.push_back(std::move(message));
    return std::nullopt;
  });
}

Problem rig(const ScenarioReader& reader, const YAML::Node& node, BalbotRig& out) {
  const std::string text = node.IsScalar() ? node.Scalar() : "";
  if (text == "on_ground") {
    out = BalbotRig::on_ground;
  } else if (text == "held_in_air") {
    out = BalbotRig::held_in_air;
  } else if (text == "wheels_driven") {
    out = BalbotRig::wheels_driven;
  } else {
    return reader.at(node, "rig: expected on_ground, held_in_air or wheels_driven, got '" + text + "'");
  }
  return std::nullopt;
}

Problem read(const ScenarioReader& reader, const YAML::Node& root, BalbotScenario& s) {
  if (!root || root.IsNull()) return std::nullopt;
  if (!root.IsMap()) return reader.at(root, "expected a map of scenario keys");
  static constexpr std::array<std::string_view, 12> keys{"initial_tilt_deg",
                                                         "release_time_s",
                                                         "pushes",
                                                         "duty_disturbances",
                                                         "noise",
                                                         "seed",
                                                         "battery_v",
                                                         "wall_distance_m",
                                                         "ipc_messages",
                                                         "rig",
                                                         "driven_wheel_rev_s",
                                                         "sensor_mount_height_m"};
  if (Problem problem = reader.only(root, "", keys)) return problem;
  const auto number = [&](const char* key, double low, double high, double& out) -> Problem {
    const YAML::Node node = root[key];
    return node ? reader.number(node, key, low, high, out) : std::nullopt;
  };
  constexpr std::uint64_t any = std::numeric_limits<std::uint64_t>::max();
  if (Problem problem = number("initial_tilt_deg", -89, 89, s.initial_tilt_deg)) return problem;
  if (Problem problem = number("release_time_s", 0, unbounded, s.release_time_s)) return problem;
  if (Problem problem = number("battery_v", 0.1, 12.6, s.battery_v)) return problem;
  if (Problem problem = number("wall_distance_m", -unbounded, unbounded, s.wall_distance_m)) return problem;
  if (Problem problem = number("sensor_mount_height_m", 0, 0.5, s.sensor_mount_height_m)) return problem;
  if (Problem problem = number("driven_wheel_rev_s", -100, 100, s.driven_wheel_rev_s)) return problem;
  if (const YAML::Node n = root["noise"]) {
    if (Problem problem = reader.boolean(n, "noise", s.noise)) return problem;
  }
  if (const YAML::Node n = root["seed"]) {
    if (Problem problem = reader.whole(n, "seed", any, s.seed)) return problem;
  }
  if (const YAML::Node n = root["rig"]) {
    if (Problem problem = rig(reader, n, s.rig)) return problem;
  }
  if (const YAML::Node n = root["pushes"]) {
    if (Problem problem = pulses(reader, n, "pushes", "force_n", -unbounded, unbounded, s.pushes)) return problem;
  }
  if (const YAML::Node n = root["duty_disturbances"]) {
    if (Problem problem = pulses(reader, n, "duty_disturbances", "duty", -1, 1, s.duty_disturbances)) return problem;
  }
  if (const YAML::Node n = root["ipc_messages"]) {
    if (Problem problem = messages(reader, n, s.ipc_messages)) return problem;
  }
  return std::nullopt;
}

}  // namespace

Result<BalbotScenario> parse_balbot_scenario(const std::string& text, const std::string& file) {
  const ScenarioReader reader{file};
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& error) {
    return Failure{file + ":" + std::to_string(error.mark.line + 1) + ": " + error.msg};
  }
  BalbotScenario scenario;
  try {
    if (Problem problem = read(reader, root, scenario)) return *problem;
  } catch (const YAML::Exception& error) {  // a node of an unexpected kind the checks above did not foresee
    return Failure{file + ":" + std::to_string(error.mark.line + 1) + ": " + error.msg};
  }
  return scenario;
}

Result<BalbotScenario> load_balbot_scenario(const std::string& path) {
  Result<std::string> text = read_text_file(path);
  if (!text) return Failure{text.error()};
  return parse_balbot_scenario(text.value(), path);
}

}  // namespace duet::plant
