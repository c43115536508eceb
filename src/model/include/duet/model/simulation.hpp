#pragma once
// `duet sim`: a model run on the PC against a plant, in lock-step time. The executive runs the model's tasks on the
// host port (duet/host/lock_step_port.hpp) exactly as it runs the firmware's: the base rate every base period, the
// slower rates at their multiples (single-tasking, fastest first), interrupt tasks when the plant raises their
// interrupt. Nothing depends on the PC's clock or scheduling, so every run with the same inputs gives the same
// values, bit for bit.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "duet/host/lock_step_port.hpp"
#include "duet/model/interpreter.hpp"
#include "duet/model/program.hpp"
#include "duet/plant/plant.hpp"
#include "duet/rt/executive.hpp"
#include "duet/rt/task_table.hpp"
#include "duet/support/result.hpp"

namespace duet::model {

struct SimulationOptions {
  double duration_s = 1.0;
  // Signals to record by name; none: the measurable ones, or every signal if none is measurable.
  std::vector<std::string> signals;
  // Called before each base tick, before the plant moves: where a test or a master tunes parameters.
  std::function<void(std::uint64_t tick, Interpreter& model)> before_tick;
  // Also record what the plant shows of itself (Plant::observables), as columns "plant.NAME" after the model's.
  bool record_plant = true;
};

// One column per element of a recorded signal ("theta", or "x[0]", "x[1]" for a vector), one row per base tick:
// the values after that tick's tasks ran.
struct Recording {
  std::vector<std::string> names;
  std::vector<std::string> units;
  // Per column, the index of the program's signal it records an element of (Program::signals), so that a file
  // format with types can store its exact type; none for one of the plant's. Empty: no column is a signal's.
  std::vector<std::optional<std::size_t>> signals;
  std::vector<double> time_s;
  std::vector<std::vector<double>> columns;
};

struct SimulationResult {
  Recording recording;
  std::uint64_t ticks = 0;
  std::vector<std::uint32_t> activations;  // per task
  std::string plant_stop;  // why the plant ended the run early (Plant::halted), the tick it asked in recorded
};

[[nodiscard]] Result<SimulationResult> simulate(const Program& program, plant::Plant& plant,
                                                const SimulationOptions& options);

// A program on the executive in lock-step, one base tick at a time: what simulate() runs, and what runs a plant
// that is itself a model (model_plant.hpp).
class ModelRunner {
 public:
  // `program` and `plant` must outlive the runner.
  static Result<std::unique_ptr<ModelRunner>> create(const Program& program, plant::Plant& plant);
  ModelRunner(const ModelRunner&) = delete;
  ModelRunner& operator=(const ModelRunner&) = delete;
  ~ModelRunner();

  void tick();                             // one base period: the base rate and whatever else is due
  void raise(std::string_view interrupt);  // runs the interrupt tasks that interrupt triggers, now
  [[nodiscard]] Interpreter& interpreter() { return *interpreter_; }
  [[nodiscard]] double base_period_s() const;
  [[nodiscard]] std::uint32_t activations(std::size_t task) const;

 private:
  using Executive = rt::Executive<host::LockStepPort, 16>;
  explicit ModelRunner(const Program& program);

  const Program& program_;
  std::unique_ptr<UserCodeLibrary> user_code_;
  std::unique_ptr<Interpreter> interpreter_;
  std::vector<rt::Task> tasks_;
  rt::ModelDescription description_;
  std::unique_ptr<host::LockStepPort> port_;
  std::unique_ptr<Executive> executive_;
};

// The executive's view of the program's tasks, in the task table's order (duet/rt/task_table.hpp): periodic rates
// fastest first, then interrupt tasks. Priorities: an interrupt task's group is the model's; the periodic rates take
// the groups after the least urgent interrupt task (the base rate first), or start at 1 without interrupt tasks.
struct TaskPriorities {
  std::vector<rt::InterruptPriority> priorities;
};
[[nodiscard]] Result<TaskPriorities> task_priorities(const Program& program);

// The recording as CSV: `time_s,name,...`, numbers exact (they read back as the same doubles).
[[nodiscard]] std::string to_csv(const Recording& recording);

}  // namespace duet::model
