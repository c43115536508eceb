#pragma once
// The executive's account as the status message's `executive` member (docs/DASHBOARD.md): time_s, ticks, core_load,
// overruns, and per task its activations, overruns and min/mean/max times in microseconds. One function for both
// back ends: duet-bridge gets the account from the application channel, duet monitor from XCP memory.

#include <nlohmann/json.hpp>

#include "duet/app_channel/host/peer.hpp"

namespace duet::dashboard {

nlohmann::json executive_status(const app_channel::host::ExecutiveReport& report);

}  // namespace duet::dashboard
