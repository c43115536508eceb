#pragma once
// The executive's account for the dashboard's Status page, every board alike: refreshed in memory, where XCP reads
// it at the A2L's addresses (balbot::xcp::executive_account), and from there published on the application channel.
// From the background loop, once per second of model time.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "balbot_xcp.hpp"
#include "duet/app_channel/endpoint.hpp"
#include "duet/rt/task_table.hpp"
#include "robot_channels.hpp"

namespace balbot::firmware {

class AccountPublisher {
 public:
  explicit AccountPublisher(const duet::rt::ModelDescription& model) : model_(model) {}

  // `cycle_hz`: what the executive's cycle counts count.
  template <typename Executive>
  void publish(const Executive& executive, std::uint32_t cycle_hz) {
    const auto& account = balbot::xcp::executive_account;
    balbot::xcp::executive_account.update(executive, cycle_hz);
    const std::size_t count = account.tasks.size() < tasks_.size() ? account.tasks.size() : tasks_.size();
    for (std::size_t task = 0; task < count; ++task) {
      const duet::rt::TaskAccount& figures = account.tasks[task];
      tasks_[task] = {model_.tasks[task].name, figures.activations, figures.overruns,
                      figures.min_cycles,      figures.mean_cycles, figures.max_cycles};
    }
    publish_executive({.ticks = executive.ticks(),  // all 64 bits; the account keeps the low 32
                       .base_period_ns = model_.base_period_ns,
                       .busy_ppm = account.busy_ppm,
                       .overruns = account.overruns,
                       .cycle_hz = account.cycle_hz,
                       .tasks = std::span{tasks_}.first(count)});
  }

 private:
  const duet::rt::ModelDescription& model_;
  std::array<duet::app_channel::TaskReport, 16> tasks_{};
};

}  // namespace balbot::firmware
