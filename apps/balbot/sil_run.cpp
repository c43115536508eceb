#include "sil_run.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "balbot.hpp"
#include "duet/hardware/hardware.hpp"
#include "duet/host/lock_step_port.hpp"
#include "duet/model/data_type.hpp"
#include "duet/rt/executive.hpp"
#include "duet/support/number_text.hpp"
#include "duet/support/text_file.hpp"

namespace duet::sil {
namespace {

// The generated hardware calls reach `plant` for as long as this lives.
class HardwareConnection {
 public:
  explicit HardwareConnection(plant::Plant& plant) { hardware::connect(&plant); }
  ~HardwareConnection() { hardware::connect(nullptr); }
  HardwareConnection(const HardwareConnection&) = delete;
  HardwareConnection& operator=(const HardwareConnection&) = delete;
};

// The generated task table names each interrupt task after its interrupt: the plant's names map to task indices.
std::vector<std::pair<std::string_view, std::size_t>> interrupt_tasks(const rt::ModelDescription& description) {
  std::vector<std::pair<std::string_view, std::size_t>> tasks;
  for (std::size_t task = 0; task < description.tasks.size(); ++task) {
    if (description.tasks[task].kind == rt::TaskKind::interrupt) tasks.emplace_back(description.tasks[task].name, task);
  }
  return tasks;
}

}  // namespace

Result<SilResult> run_sil(plant::Plant& plant, const SilOptions& options) {
  const rt::ModelDescription& description = balbot::description;
  const double period_s = description.base_period_ns * 1e-9;
  if (!(options.duration_s >= 0) || !std::isfinite(options.duration_s)) {
    return Failure{"the duration must be a number of seconds, 0 or more"};
  }
  const auto ticks = static_cast<std::uint64_t>(std::floor(options.duration_s / period_s + 1e-9)) + 1U;
  const auto settled_from = static_cast<std::uint64_t>(std::llround(4.0 / period_s));

  // A fresh start: what a reset gives the firmware on the board (zeroed RAM, the parameters' initial values).
  balbot::signals = balbot::Signals{};
  balbot::parameters = balbot::reference_parameters;
  if (Status started = plant.start(period_s); !started) return Failure{started.error()};
  const HardwareConnection connection{plant};
  host::LockStepPort port{description};
  port.on_task_finished = options.task_finished;
  rt::Executive<host::LockStepPort, 16> executive{description, port};
  port.attach(executive);
  if (const rt::TaskTableError error = executive.initialize(); error != rt::TaskTableError::none) {
    return Failure{"the executive refused the firmware's task table (error " + std::to_string(static_cast<int>(error)) +
                   ")"};
  }
  if (!executive.begin()) return Failure{"the executive did not start"};

  const auto interrupts = interrupt_tasks(description);
  const plant::RaiseInterrupt raise = [&](std::string_view interrupt) {
    for (const auto& [name, task] : interrupts) {
      if (name == interrupt) port.raise(task);
    }
  };
  SilResult result;
  if (options.measurements != nullptr) result.recording = options.measurements->empty_recording();
  Status failure = done();
  for (std::uint64_t tick = 0; tick < ticks; ++tick) {
    const double now = static_cast<double>(tick) * period_s;
    if (options.pacer != nullptr) options.pacer->wait_until(now);
    std::unique_lock<std::mutex> held;
    if (options.memory_lock != nullptr) held = std::unique_lock{*options.memory_lock};
    if (options.tick_started) options.tick_started(now);
    plant.advance(now, raise);
    port.advance(1);
    if (options.measurements != nullptr) options.measurements->record(now, result.recording);
    result.ticks = tick + 1;
    const double theta = balbot::signals.theta;
    result.final_theta_deg = theta;
    if (tick >= settled_from) {
      result.largest_theta_after_4_s_deg = std::max(result.largest_theta_after_4_s_deg.value_or(0), std::abs(theta));
    }
    if (options.check) {
      if (auto checked = options.check(); !checked) {
        failure = Failure{"at " + shortest_text(now) + " s (tick " + std::to_string(tick) + "): " + checked.error()};
        break;
      }
    }
  }
  executive.end();
  if (!failure) return Failure{failure.error()};
  return result;
}

Result<Measurements> balbot_measurements() {
  auto text = read_text_file(DUET_BALBOT_A2L);
  if (!text) return Failure{text.error()};
  return Measurements::from_a2l(text.value(), DUET_BALBOT_A2L, &balbot::signals, sizeof(balbot::Signals));
}

}  // namespace duet::sil
