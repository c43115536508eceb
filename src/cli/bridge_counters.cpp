#include "bridge_counters.hpp"

#include <charconv>

namespace duet::cli {
namespace {

// Reads the number after `label` in `text` (from the label on) into `value`; false if either is missing.
bool number_after(std::string_view& text, std::string_view label, std::uint64_t& value) {
  const std::size_t found = text.find(label);
  if (found == std::string_view::npos) return false;
  text.remove_prefix(found + label.size());
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{}) return false;
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  return true;
}

}  // namespace

std::optional<XcpTraffic> parse_bridge_counters(std::string_view output) {
  constexpr std::string_view marker = "duet-bridge: stopped; ";
  const std::size_t start = output.rfind(marker);
  if (start == std::string_view::npos) return std::nullopt;
  std::string_view line = output.substr(start);
  line = line.substr(0, line.find('\n'));
  XcpTraffic traffic;
  // In the order the bridge prints them.
  if (!number_after(line, "frames to master ", traffic.frames_to_master) ||
      !number_after(line, " (", traffic.bytes_to_master) ||
      !number_after(line, " to slave ", traffic.frames_to_slave) || !number_after(line, " (", traffic.bytes_to_slave) ||
      !number_after(line, "DAQ frames dropped ", traffic.daq_frames_dropped) ||
      !number_after(line, "masters served ", traffic.masters_served)) {
    return std::nullopt;
  }
  return traffic;
}

}  // namespace duet::cli
