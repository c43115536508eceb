#pragma once
// What a block's mapping sees (import.cpp walks the systems, block_mappings.cpp maps one block at a time): the block,
// its path, its signals by port, its parameters (as stored, else the file's defaults, else the built-in ones),
// evaluated in its workspace; and where it says what it made, or why it refuses.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "duet/simulink_import/import.hpp"
#include "duet/simulink_import/simulink_model.hpp"
#include "duet_text.hpp"

namespace duet::simulink_import {

class ImportContext;

// `text` without the spaces, tabs and newlines around it.
[[nodiscard]] std::string trimmed(const std::string& text);
// A block's parameter as stored, trimmed, or `otherwise` where the block does not store it.
[[nodiscard]] std::string stored_or(const Block& block, const char* name, const char* otherwise);

// Whether a Simulink data type (an OutDataTypeStr) is one of duet's, which have the same names: double, single,
// int8 ... uint32, boolean.
[[nodiscard]] bool is_duet_type(const std::string& type);

// What a block is: a library link by what it links to (its SourceType, "PID 1dof"), any other by its BlockType.
[[nodiscard]] std::string type_name(const Block& block);

// Turns `context.block()` into duet blocks (context.emit) or refuses it (context.refuse).
using BlockMapping = void (*)(ImportContext& context);

// The mapping of a block type (or a library link's SourceType, "PID 1dof"); nothing for one duet cannot import.
[[nodiscard]] BlockMapping mapping_for(const std::string& type);

// The model-wide side a block's mapping needs: parameters it makes, the base period, the file's defaults.
class ImportModel {
 public:
  virtual ~ImportModel() = default;
  // A parameter's duet text: a model parameter's name when `expression` is a variable of the --variables files
  // (`Kp`, `P.pid.Kp` -> P_pid_Kp), which then stays tunable; else the value evaluated as a literal.
  // `parameter` names it in messages (Gain 'Kx': unresolved name 'Kx').
  virtual std::optional<std::string> parameter_text(ImportContext& context, const std::string& parameter,
                                                    const std::string& expression) = 0;
  [[nodiscard]] virtual long long base_period_us() const = 0;
  [[nodiscard]] virtual const SimulinkModel& source() const = 0;
};

class ImportContext {
 public:
  ImportContext(ImportModel& model, const Block& block, std::string path, const Workspace& workspace,
                std::vector<std::string> inputs, std::vector<std::string> outputs)
      : model_(model),
        block_(block),
        path_(std::move(path)),
        workspace_(workspace),
        inputs_(std::move(inputs)),
        outputs_(std::move(outputs)) {}

  [[nodiscard]] const Block& block() const { return block_; }
  [[nodiscard]] const std::string& path() const { return path_; }
  [[nodiscard]] const Workspace& workspace() const { return workspace_; }
  [[nodiscard]] ImportModel& model() { return model_; }

  // The parameter as the block has it: stored, else the file's BlockParameterDefaults, else the built-in default
  // of the file's release; a library link's mask values first. Refuses (and returns nothing) when none is known.
  std::optional<std::string> raw(const std::string& name);
  // The parameter evaluated in the block's workspace; refuses when it is not a number (or not a matrix of them).
  std::optional<Value> value(const std::string& name);
  // A scalar of it, and refuses otherwise.
  std::optional<double> scalar(const std::string& name);
  // As the duet parameter's text: a tunable model parameter's name, or the literal.
  std::optional<std::string> parameter(const std::string& name);
  // Whether the parameter, as the block has it, is `expected` (after trimming); refuses with `what` otherwise.
  bool require(const std::string& name, const std::string& expected, const std::string& what);

  // The signal on input port `port` (1-based); refuses when it is not connected.
  std::optional<std::string> input(std::size_t port);
  [[nodiscard]] std::size_t input_count() const { return inputs_.size(); }
  // The signal output port `port` drives; a name nobody reads when nothing is connected (duet needs one).
  std::string output(std::size_t port);
  [[nodiscard]] std::size_t output_count() const { return outputs_.size(); }

  // `period_us: N` from the SampleTime parameter `name` (empty when inherited, -1), or `period: constant` (inf);
  // refuses continuous (0), offsets, and periods that are no multiple of the base period.
  std::optional<std::string> period(const std::string& name = "SampleTime");

  // The duet block's name and source comment filled in from the Simulink block; a mapping may emit several.
  void emit(DuetBlock block, const std::string& what);
  void refuse(const std::string& reason);
  // The block emitted last computes as the Simulink block only in floating point, for `why`.
  void floating_only(const std::string& why) {
    if (!emitted_.empty()) emitted_.back().floating_only = why;
  }
  // What the block became, for the report, where its blocks were emitted without saying.
  void emit_note(const std::string& what) { what_ += (what_.empty() ? "" : "; ") + what; }

  [[nodiscard]] bool refused() const { return refused_; }
  [[nodiscard]] std::vector<DuetBlock>& emitted() { return emitted_; }
  [[nodiscard]] const std::string& what() const { return what_; }
  [[nodiscard]] const std::string& reason() const { return reason_; }
  // Names for the duet blocks and signals a mapping adds of its own, unique in the system.
  std::string new_block_name(const std::string& stem) { return block_namer_(stem); }
  std::string new_signal_name(const std::string& stem) { return signal_namer_(stem); }
  using Namer = std::function<std::string(const std::string&)>;
  void set_namers(Namer blocks, Namer signals) {
    block_namer_ = std::move(blocks);
    signal_namer_ = std::move(signals);
  }
  std::string block_name;  // the duet name of the (first) block it makes

 private:
  ImportModel& model_;
  const Block& block_;
  std::string path_;
  const Workspace& workspace_;
  std::vector<std::string> inputs_;
  std::vector<std::string> outputs_;
  std::vector<DuetBlock> emitted_;
  bool refused_ = false;
  std::string what_;
  std::string reason_;
  Namer block_namer_;
  Namer signal_namer_;
};

}  // namespace duet::simulink_import
