#pragma once
// A measurement the page downloads as an MDF4 file (docs/DASHBOARD.md, "Saving as MDF4"): one group, its time
// channel and one channel per signal, written by src/mdf4. A signal is stored in the type its description names
// when every value fits that type exactly, else as f64 (and its comment says why), so that nothing is rounded.

#include <cstdint>
#include <string>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::dashboard {

struct MeasuredSignal {
  std::string name;
  std::string unit;
  std::string described_type;  // the description's: uint8 ... int64, float32, float64; empty: not known
  std::vector<double> values;  // as long as the time; NaN is a missing sample
};

struct Measurement {
  std::string group_name;
  std::string group_comment;
  std::string file_comment;
  std::int64_t start_time_ns = 0;
  std::vector<double> time_s;  // finite, not decreasing
  std::vector<MeasuredSignal> signals;
};

// The file's bytes; fails naming the problem (a time that goes back, a temporary file that cannot be written).
Result<std::string> mdf4_bytes(const Measurement& measurement);

// The header's start time for times on the target's clock: `now_ns` less the newest time, so that the file's
// absolute times come near the wall clock (the target's clock starts at its boot, not at a known date); `now_ns`
// itself when the newest time is not between 0 and `now_ns`.
std::int64_t start_time_ns(double newest_time_s, std::int64_t now_ns);

}  // namespace duet::dashboard
