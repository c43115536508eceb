#include "duet/studio/simulation_job.hpp"

#include <chrono>
#include <cmath>

#include "duet/model/simulation.hpp"
#include "duet/model/simulation_plant.hpp"
#include "duet/studio/model_view.hpp"

namespace duet::studio {

using nlohmann::json;

namespace {

// Thrown from the tick hook to leave the simulation early; caught in run().
struct Cancelled {};

json error_message(const json& id, const std::string& text) {
  return {{"type", "error"}, {"request", "simulate"}, {"id", id}, {"message", "simulate: " + text}};
}

}  // namespace

SimulationJob::SimulationJob(SimulationRequest request, std::function<void(double)> progress,
                             std::function<void(json)> finished)
    : request_(std::move(request)), progress_(std::move(progress)), finished_(std::move(finished)) {
  thread_ = std::thread{[this] { run(); }};
}

SimulationJob::~SimulationJob() {
  cancel();
  thread_.join();
}

void SimulationJob::run() {
  const CheckedText checked = check_text(request_.text, request_.model_file);
  if (!checked.program) return finished_(error_message(request_.id, "the model has errors: fix them first"));
  auto plant = model::make_simulation_plant(request_.plant, request_.scenario, std::nullopt);
  if (!plant) return finished_(error_message(request_.id, plant.error()));
  if (!(request_.duration_s > 0) || request_.duration_s > 3600)
    return finished_(error_message(request_.id, "duration_s must be more than 0 and at most 3600"));

  const double ticks = request_.duration_s * 1e6 / checked.model->base_period_us;
  auto reported = std::chrono::steady_clock::now();
  model::SimulationOptions options{request_.duration_s, {}, {}};
  options.before_tick = [&](std::uint64_t tick, model::Interpreter&) {
    if (cancelled_) throw Cancelled{};
    if (const auto now = std::chrono::steady_clock::now(); now - reported >= std::chrono::milliseconds{100}) {
      reported = now;
      progress_(static_cast<double>(tick) / ticks);
    }
  };
  try {
    auto simulated = model::simulate(*checked.program, *plant.value().plant, options);
    if (!simulated) return finished_(error_message(request_.id, simulated.error()));
    const model::Recording& recording = simulated.value().recording;
    const std::size_t rows = recording.time_s.size();
    const std::size_t step = rows <= max_rows ? 1 : (rows + max_rows - 1) / max_rows;
    json time = json::array();
    json columns = json::array();
    for (std::size_t row = 0; row < rows; row += step) time.push_back(recording.time_s[row]);
    for (const std::vector<double>& column : recording.columns) {
      json values = json::array();
      for (std::size_t row = 0; row < rows; row += step) values.push_back(column[row]);
      columns.push_back(std::move(values));
    }
    finished_({{"type", "simulation"},
               {"id", request_.id},
               {"names", recording.names},
               {"units", recording.units},
               {"time_s", std::move(time)},
               {"columns", std::move(columns)},
               {"decimated_by", step},
               {"warnings", plant.value().warnings},
               {"cancelled", false}});
  } catch (const Cancelled&) {
    finished_({{"type", "simulation"},
               {"id", request_.id},
               {"names", json::array()},
               {"units", json::array()},
               {"time_s", json::array()},
               {"columns", json::array()},
               {"decimated_by", 1},
               {"cancelled", true}});
  }
}

}  // namespace duet::studio
