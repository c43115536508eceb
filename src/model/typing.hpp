#pragma once
// For build_program (private to src/model): what type and size each block's outputs have, given its inputs, and
// whether its inputs and parameters fit what it computes (docs/MODELS.md, "Values and types").

#include <optional>
#include <vector>

#include "duet/model/diagnostic.hpp"
#include "duet/model/program.hpp"

namespace duet::model {

using KnownTypes = std::vector<std::optional<SignalType>>;

// The outputs' types as far as the known inputs tell; an output stays unknown until they do. In a loop where every
// block waits for another, `guess_scalars` lets blocks whose output type does not depend on their inputs' type (Not,
// Compare, Logic, Convert) take unknown inputs for scalars.
[[nodiscard]] KnownTypes infer_outputs(const Program& program, const ProgramBlock& block, const KnownTypes& inputs,
                                       bool guess_scalars);

// Once every signal is typed: inputs that disagree, parameters of the wrong type or size, types a block cannot
// compute in.
void check_types(const Program& program, const ProgramBlock& block, std::vector<Diagnostic>& diagnostics);

}  // namespace duet::model
