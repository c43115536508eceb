#pragma once
// For code generation (private to src/model): where each signal lives in generated code, the layout of the
// generated structures, and the C++ text of values and of each block's two phases.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "duet/model/program.hpp"

namespace duet::model {

// A member of a generated structure, at the offset the generator fixes (natural alignment, in model order).
struct Field {
  std::string name;
  DataType type = DataType::float64;
  std::size_t count = 1;
  std::size_t offset = 0;
};
[[nodiscard]] std::vector<Field> lay_out(std::vector<Field> fields, std::size_t& size);

// A value of `type` as C++ writes it exactly: 0.1F, 2.5, std::int16_t{-3}, true,
// -std::numeric_limits<float>::infinity().
[[nodiscard]] std::string literal(DataType type, double value);

class Generator {
 public:
  explicit Generator(const Program& program);

  // Signals that live in the Signals structure: measurable, read in another task, computed at initialisation, or
  // held by an enabled subsystem. The others are locals of their task's step function.
  [[nodiscard]] bool is_member(std::size_t signal) const { return member_[signal]; }
  [[nodiscard]] std::vector<Field> signal_fields() const;
  [[nodiscard]] std::vector<Field> parameter_fields() const;

  // Whether the block's name stands bare in the code, as a member of the State structure.
  [[nodiscard]] static bool has_state_member(const ProgramBlock& block);
  // Declarations of the State structure's members and their reset in initialize().
  [[nodiscard]] std::string state_members() const;
  [[nodiscard]] std::string state_resets() const;
  // Namespace-scope constants the blocks need (pins, literal tables).
  [[nodiscard]] std::string block_constants() const;

  // The statements of a block's phase (indented), with locals declared where their driver computes them.
  [[nodiscard]] std::string output_phase(std::size_t block) const;
  [[nodiscard]] std::string update_phase(std::size_t block) const;
  // What a task's step function does first and last: the release flags of its deterministic rate transitions.
  [[nodiscard]] std::string task_prologue(std::size_t task) const;
  [[nodiscard]] std::string task_epilogue(std::size_t task) const;

 private:
  [[nodiscard]] std::string storage(std::size_t signal) const;  // the variable, without a subscript
  [[nodiscard]] std::string element(std::size_t signal, std::size_t index) const;
  [[nodiscard]] std::string element(std::size_t signal, const std::string& index) const;
  [[nodiscard]] std::string pointer(std::size_t signal) const;
  [[nodiscard]] std::string argument(const ProgramBlock& block, const std::string& name, double fallback, DataType type,
                                     const std::string& index) const;
  // A Code block's parameter element in its declared type.
  [[nodiscard]] std::string argument_value(const ProgramBlock& block, const std::string& name, DataType type,
                                           std::size_t index) const;
  [[nodiscard]] std::string state(const ProgramBlock& block, const std::string& index) const;
  [[nodiscard]] std::string code_call(const ProgramBlock& block) const;
  [[nodiscard]] std::string declare_outputs(const ProgramBlock& block) const;
  [[nodiscard]] std::string guarded(const ProgramBlock& block, std::string statements) const;
  [[nodiscard]] std::string output_statements(const ProgramBlock& block) const;
  [[nodiscard]] std::string update_statements(const ProgramBlock& block) const;
  [[nodiscard]] std::string hardware_output(const ProgramBlock& block) const;
  [[nodiscard]] std::string plant_resource_access(const ProgramBlock& block) const;
  [[nodiscard]] std::string converted(std::size_t signal, std::size_t index, DataType type) const;
  [[nodiscard]] std::string every_element(const std::vector<std::size_t>& signals, DataType type) const;
  [[nodiscard]] std::string release_flag(const ProgramBlock& block, std::string& statements) const;
  [[nodiscard]] static std::string shared_countdown(std::size_t task, std::uint32_t ratio);
  [[nodiscard]] std::vector<std::pair<std::size_t, std::uint32_t>> shared_countdowns() const;  // (task, ratio)
  [[nodiscard]] std::string source_output(const ProgramBlock& block) const;
  // A DiscretePid's gain: its input where connected, else its parameter.
  [[nodiscard]] std::string pid_gain(const ProgramBlock& block, const std::string& name, DataType type) const;
  // A DiscretePid's external reset as a further argument (", signal"), or nothing when it is not connected.
  [[nodiscard]] std::string pid_reset(const ProgramBlock& block) const;
  [[nodiscard]] std::string bytes_output(const ProgramBlock& block) const;
  // A block parameter as a `const T*`: a tunable parameter's array, or the block's constant array of the literal.
  [[nodiscard]] std::string array_argument(const ProgramBlock& block, const std::string& name, DataType type) const;
  // Blocks whose state's size is a template argument: TransferFunction, StateSpace, MovingAverage, KalmanFilter.
  [[nodiscard]] std::string sized_state_type(const ProgramBlock& block) const;
  [[nodiscard]] std::string sized_state_reset(const ProgramBlock& block) const;
  [[nodiscard]] std::string sized_state_output(const ProgramBlock& block) const;
  [[nodiscard]] std::string sized_state_update(const ProgramBlock& block) const;
  [[nodiscard]] std::string rate_transition_output(const ProgramBlock& block) const;
  [[nodiscard]] std::string rate_transition_update(const ProgramBlock& block) const;

  const Program& program_;
  std::vector<bool> member_;
  std::vector<std::optional<std::string>> inlined_;  // a literal Constant's value, written where it is read
};

}  // namespace duet::model
