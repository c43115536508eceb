#pragma once
// Where the executive's account lies in the target's memory, from the `executive.*` measurements of an A2L that
// duet gen wrote (duet/rt/executive_account.hpp), and what its bytes say: the `executive` member of the dashboard's
// status message (docs/DASHBOARD.md). duet monitor uploads the segment once a second.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "duet/xcp/host/a2l.hpp"

namespace duet::monitor {

class ExecutiveAccountLayout {
 public:
  // None when the A2L describes no account (a target whose firmware keeps none, or an older generation).
  static std::optional<ExecutiveAccountLayout> from(const xcp::host::A2lDescription& a2l);

  [[nodiscard]] const xcp::host::MemoryInfo& segment() const { return segment_; }
  // The account as the status message's `executive` (dashboard::executive_status). `bytes` are the segment's, as
  // uploaded; `base_period_ns` the executive's base period, which the account does not hold.
  [[nodiscard]] nlohmann::json decode(std::span<const std::uint8_t> bytes, std::uint32_t base_period_ns) const;

 private:
  struct Task {
    std::string name;
    std::array<std::optional<std::uint32_t>, 5> offsets;  // activations, overruns, min, mean, max cycles
  };
  xcp::host::MemoryInfo segment_;
  std::array<std::optional<std::uint32_t>, 4> offsets_;  // ticks, busy_ppm, overruns, cycle_hz
  std::vector<Task> tasks_;
};

}  // namespace duet::monitor
