#pragma once
// What a model means, checked (docs/MODELS.md, "Validation"): block types, ports and parameters, one driver per
// signal, every input driven, references to parameters and constants, algebraic loops, rates meeting without a
// RateTransition (rates.hpp); unused parameters, constants and signal declarations as warnings. Every diagnostic has
// the place, what is wrong, and a hint.

#include <vector>

#include "duet/model/diagnostic.hpp"
#include "duet/model/model.hpp"

namespace duet::model {

[[nodiscard]] std::vector<Diagnostic> validate(const Model& model);

}  // namespace duet::model
