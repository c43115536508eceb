#pragma once
// A simulation from duet studio's page (docs/STUDIO.md, `simulate`): the model's text against a plant, on a thread of
// its own so that the page stays served, reporting its progress and cancellable between ticks. The result is
// thinned to at most `max_rows` rows (every k-th tick), which the message says.

#include <nlohmann/json.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <thread>

namespace duet::studio {

struct SimulationRequest {
  std::string text;
  std::string model_file;  // where the text's Code blocks find their headers
  std::string plant;       // a name, or a plant model's path
  std::string scenario;    // the robot's scenario file, or empty
  double duration_s = 1;
  nlohmann::json id;
};

class SimulationJob {
 public:
  static constexpr std::size_t max_rows = 20'000;

  // Both called on the job's thread: `progress` with the fraction done (at most ten times a second), `finished` once
  // with the `simulation` or `error` message.
  SimulationJob(SimulationRequest request, std::function<void(double)> progress,
                std::function<void(nlohmann::json)> finished);
  ~SimulationJob();  // cancels and waits
  SimulationJob(const SimulationJob&) = delete;
  SimulationJob& operator=(const SimulationJob&) = delete;

  void cancel() { cancelled_ = true; }
  [[nodiscard]] const nlohmann::json& id() const { return request_.id; }

 private:
  void run();

  SimulationRequest request_;
  std::function<void(double)> progress_;
  std::function<void(nlohmann::json)> finished_;
  std::atomic<bool> cancelled_{false};
  std::thread thread_;
};

}  // namespace duet::studio
