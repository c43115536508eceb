#pragma once
// A Simulink model brought over as a duet model (`duet import simulink`, docs/IMPORT.md): the discrete subset whose
// semantics duet's blocks have exactly, parameters evaluated as the MATLAB subset, tunable parameters kept as model
// parameters of their names. Strict: a block or an option it cannot prove equal refuses the import, with the block's
// path, the reason and what to do; the report lists every block with its verdict either way.

#include <cstdint>
#include <functional>
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

// A duet block that computes as its Simulink block only in floating point: for integers the two differ (Simulink
// saturates an overflow where duet's Sum wraps). The import has no types; the checked model has.
struct FloatingOnly {
  std::string block;   // the duet block's path: "gain", "controller/sum"
  std::string source;  // the Simulink block's path and type: "m/Sub/Add (Sum)"
  std::string why;     // "Simulink saturates an integer overflow (SaturateOnIntegerOverflow on), duet's Sum wraps ..."
};

struct ImportResult {
  std::string model_text;  // the duet model file; empty when anything was refused
  std::vector<Verdict> report;
  std::vector<std::string> problems;  // every refusal and model-wide problem, each naming its place
  std::vector<FloatingOnly> floating_only;
};

[[nodiscard]] ImportResult import_simulink(const SimulinkModel& model, const ImportOptions& options);

// What `result`'s floating-only blocks refuse once the model is checked: one problem for each that computes in an
// integer type. `output_type` gives a duet block's output type as the checked model has it ("int16", "double[3]").
[[nodiscard]] std::vector<std::string> integer_problems(
    const ImportResult& result, const std::function<std::string(const std::string& block)>& output_type);

}  // namespace duet::simulink_import
