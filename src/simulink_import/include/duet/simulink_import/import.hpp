#pragma once
// A Simulink model brought over as a duet model (`duet import simulink`, docs/IMPORT.md): the discrete subset whose
// semantics duet's blocks have exactly, parameters evaluated as the MATLAB subset, tunable parameters kept as model
// parameters of their names. Strict: a block or an option it cannot prove equal refuses the import, with the block's
// path, the reason and what to do; the report lists every block with its verdict either way.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "duet/simulink_import/matlab_expression.hpp"
#include "duet/simulink_import/simulink_model.hpp"

namespace duet::simulink_import {

// A function-call subsystem as an interrupt task (`--interrupt PATH=IRQ:PRIORITY`).
struct InterruptTask {
  std::string interrupt;
  int priority = 0;
};

struct ImportOptions {
  Workspace variables;                              // from the --variables files, in order
  std::optional<std::uint32_t> base_period_us;      // instead of the solver's fixed step
  std::map<std::string, InterruptTask> interrupts;  // by block path ("model/Sub/ISR")
};

// One Simulink block and what became of it.
struct Verdict {
  std::string path;  // "tilt_loop/Scale/times k"
  std::string type;  // its BlockType, or a library link's SourceType
  bool imported = false;
  std::string what;  // "Gain k: 2.5", or why it is refused and what to do
};

struct ImportResult {
  std::string model_text;  // the duet model file; empty when anything was refused
  std::vector<Verdict> report;
  std::vector<std::string> problems;  // every refusal and model-wide problem, each naming its place
};

[[nodiscard]] ImportResult import_simulink(const SimulinkModel& model, const ImportOptions& options);

}  // namespace duet::simulink_import
