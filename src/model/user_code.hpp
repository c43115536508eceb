#pragma once
// For simulation and generation (private to src/model): a Code block's function takes four structures — its inputs,
// outputs, state and parameters — declared from the model (docs/MODELS.md, "User code"). Generated code and the
// simulation's compiled user code declare them from the same text, and the interpreter lays out its bytes by the
// same offsets.

#include <cstddef>
#include <string>
#include <vector>

#include "duet/model/program.hpp"
#include "generator.hpp"

namespace duet::model {

struct CodeInterface {
  std::vector<Field> inputs;
  std::vector<Field> outputs;
  std::vector<Field> state;
  std::vector<Field> parameters;
  std::size_t inputs_size = 1;
  std::size_t outputs_size = 1;
  std::size_t state_size = 1;
  std::size_t parameters_size = 1;
};
[[nodiscard]] CodeInterface code_interface(const Program& program, const ProgramBlock& block);

// namespace code::BLOCK { struct Inputs {...}; struct Outputs {...}; struct State {...}; struct Parameters {...}; }
[[nodiscard]] std::string code_structures(const Program& program, const ProgramBlock& block);

// The data type of a Code block's parameter: as declared, as the model parameter it names, or double.
[[nodiscard]] DataType code_parameter_type(const Program& program, const ProgramBlock& block, const std::string& name);

}  // namespace duet::model
