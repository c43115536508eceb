#pragma once
// What the Scope page sends to be saved as MDF4 (docs/DASHBOARD.md, "Saving as MDF4"), checked strictly: the
// page's samples come from the browser, so a request may say anything. A refusal names the member and the problem.
//
//   {"time_s": [t0, t1, ...], "signals": [{"name": "theta", "unit": "deg", "values": [v0, v1, ...]}, ...]}
//
// Times finite and not decreasing; each signal named once, its values as many as the times, each a number or null
// (a gap). A signal's type is the one the back end's description gives for its name.

#include <cstddef>
#include <string_view>
#include <vector>

#include "duet/dashboard/dashboard.hpp"
#include "duet/support/result.hpp"
#include "measurement_file.hpp"

namespace duet::dashboard {

struct ScopeLimits {
  static constexpr std::size_t max_signals = 256;
  static constexpr std::size_t max_samples = 400'000;  // the page's longest ring (web/src/signal_store.js)
  // Numbers in one request, counted before parsing (a parsed number takes 16 bytes, its text as few as 2).
  static constexpr std::size_t max_numbers = 4'000'000;
};

// The measurement's group, times and signals; the caller gives the comments and the start time.
Result<Measurement> scope_measurement(std::string_view body, const std::vector<Item>& telemetry);

}  // namespace duet::dashboard
