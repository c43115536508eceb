#include "duet/dashboard/executive_status.hpp"

namespace duet::dashboard {

nlohmann::json executive_status(const app_channel::host::ExecutiveReport& report) {
  const double us_per_cycle = report.cycle_hz == 0 ? 0.0 : 1e6 / report.cycle_hz;  // cycle counts become times
  nlohmann::json executive = {{"time_s", static_cast<double>(report.ticks) * report.base_period_ns * 1e-9},
                              {"ticks", report.ticks},
                              {"core_load", report.busy_ppm * 1e-6},
                              {"overruns", report.overruns},
                              {"tasks", nlohmann::json::array()}};
  for (const auto& task : report.tasks) {
    executive["tasks"].push_back({{"name", task.name},
                                  {"activations", task.activations},
                                  {"overruns", task.overruns},
                                  {"min_us", task.min_cycles * us_per_cycle},
                                  {"mean_us", task.mean_cycles * us_per_cycle},
                                  {"max_us", task.max_cycles * us_per_cycle}});
  }
  return executive;
}

}  // namespace duet::dashboard
