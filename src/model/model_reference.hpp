#pragma once
// For the reader (private to src/model): model references, Subsystems whose blocks come from another model file
// (docs/MODELS.md, "Model references").

#include <string>
#include <vector>

#include "duet/model/model.hpp"
#include "duet/support/result.hpp"

namespace duet::model {

// Replaces each model reference in `model` by the referenced model's blocks: its Inports by the signals the reference
// binds them to, its bound Outports' signals by the referencing model's; its parameters and constants join the
// model's, its signal declarations apply inside the reference. `chain`: the files that reference this model, outermost
// first, so that a model containing itself is found. The first problem, formatted, on failure.
[[nodiscard]] Status expand_references(Model& model, const std::vector<std::string>& chain);

// The reader's load_model(), for a model referenced through `chain` (model_file.cpp).
[[nodiscard]] Result<Model> load_referenced_model(const std::string& path, const std::vector<std::string>& chain);

}  // namespace duet::model
