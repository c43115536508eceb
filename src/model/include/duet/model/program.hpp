#pragma once
// A validated model made ready to run: every signal with its type and size, every block with its inputs and outputs
// as signal numbers and its parameters resolved, and the tasks with their blocks in execution order. Simulation
// (interpreter.hpp) and code generation (generate.hpp) both work from it, so they cannot disagree on what a model
// means.
//
// A block runs in two phases, as in Simulink: `output` computes its outputs from its inputs and state, in execution
// order; `update` advances its state after every output of the task is computed. A RateTransition is the one block
// whose phases run in different tasks: its update takes the value in the writer's task, its output hands it out in
// the reader's.

#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "duet/model/diagnostic.hpp"
#include "duet/model/model.hpp"
#include "duet/model/rates.hpp"

namespace duet::model {

struct SignalType {
  DataType type = DataType::float64;
  std::vector<std::size_t> shape;  // {} scalar, {n} vector, {rows, columns} matrix
  [[nodiscard]] std::size_t elements() const;
  bool operator==(const SignalType&) const = default;
};
[[nodiscard]] std::string describe(const SignalType& type);  // "single", "single[3]", "double[2x2]"

struct ProgramSignal {
  std::string name;        // its path: "theta", or "imu/raw" inside subsystem imu
  std::string identifier;  // a C++ name: "theta", "imu_raw"
  SignalType type;
  std::string unit;
  std::string description;
  std::vector<std::string> labels;  // value k's name
  bool measurable = false;
  std::size_t driver = 0;  // the block that drives it
  // A Constant block's output that names a tunable parameter is that parameter, read where it is used, so that
  // tuning reaches every reader at once.
  std::optional<std::size_t> parameter;
};

// A block parameter, resolved.
struct Argument {
  enum class Kind : std::uint8_t { literal, parameter, word } kind = Kind::literal;
  Value value;                // literal (a constant's value too)
  std::size_t parameter = 0;  // Kind::parameter: index into Model::parameters
  std::string text;           // as written
  Location location;
};

inline constexpr std::size_t at_initialisation = static_cast<std::size_t>(-1);

struct ProgramBlock {
  std::string path;
  std::string identifier;  // a C++ name
  const Block* block = nullptr;
  std::vector<std::size_t> inputs;  // signal numbers, in the order of the type's ports (u1, u2, ... by number)
  std::vector<std::string> input_ports;
  std::vector<std::size_t> outputs;
  std::vector<std::string> output_ports;
  std::map<std::string, Argument> arguments;
  std::size_t task = 0;              // where its output phase runs; at_initialisation for constants
  std::size_t update_task = 0;       // where its update phase runs (a RateTransition: the writer's task)
  std::vector<std::size_t> enables;  // boolean signals: it runs while all are true (enabled subsystems)
  double period_s = 0;               // its task's period (0 for interrupt tasks and constants)

  [[nodiscard]] const std::string& type() const { return block->type; }
  [[nodiscard]] const Argument* argument(const std::string& name) const;
};

struct ProgramTask {
  std::string name;
  Rate rate;
  std::optional<int> priority;       // interrupt tasks
  std::vector<std::size_t> outputs;  // blocks whose output phase runs here, in execution order
  std::vector<std::size_t> updates;  // blocks whose update phase runs here, after every output
};

struct Program {
  const Model* model = nullptr;
  std::vector<ProgramSignal> signals;
  std::vector<ProgramBlock> blocks;
  std::vector<ProgramTask> tasks;            // periodic tasks fastest first, then interrupt tasks
  std::vector<std::size_t> initial_outputs;  // constant blocks, in execution order
  // Blocks the model does not spell out but implies (an edge-triggered subsystem's edge detector); ProgramBlock::block
  // points into it for those.
  std::shared_ptr<const std::deque<Block>> implied_blocks;

  [[nodiscard]] const Parameter& parameter(const Argument& argument) const {
    return model->parameters[argument.parameter];
  }
  [[nodiscard]] std::optional<std::size_t> find_signal(const std::string& name) const;
};

struct ProgramBuild {
  std::optional<Program> program;  // none when a diagnostic is an error
  std::vector<Diagnostic> diagnostics;
};

// Validates `model` (validate.hpp) and, without errors, types its signals and lays out its tasks. `model` must
// outlive the program.
[[nodiscard]] ProgramBuild build_program(const Model& model);

}  // namespace duet::model
