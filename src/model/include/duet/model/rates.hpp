#pragma once
// Which task each block runs in (docs/MODELS.md, "Sample times"): periodic rates as multiples of the base period,
// interrupt tasks of triggered subsystems, and constants computed once. Inherited rates are propagated from the
// inputs; where different rates meet without a RateTransition, or an interrupt task reads a periodic signal directly,
// a diagnostic says where and how to fix it. The task table lists the model's tasks for the executive and
// `duet sched`, with each task's blocks in execution order (direct feedthrough: a block whose output depends on its
// input in the same step runs after what drives it; a UnitDelay's output comes from its state and needs nothing).

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "duet/model/diagnostic.hpp"
#include "duet/model/model.hpp"

namespace duet::model {

struct Rate {
  enum class Kind : std::uint8_t { unknown, constant, periodic, interrupt } kind = Kind::unknown;
  std::int64_t multiple = 0;  // periodic: of the base period
  std::string interrupt;      // interrupt: the trigger's name
  bool operator==(const Rate&) const = default;
};

struct Task {
  std::string name;  // "rate 1" (the base rate), "rate 10", or the interrupt's name
  Rate rate;
  double period_us = 0;             // periodic tasks
  std::optional<int> priority;      // interrupt tasks: as the model gives it (none: `auto`)
  std::vector<std::string> blocks;  // block paths in execution order: every input computed before it is read
};

struct RateAnalysis {
  std::map<std::string, Rate> block_rates;   // by block path: "name" or "subsystem/name"
  std::vector<Task> tasks;                   // periodic tasks, fastest first, then interrupt tasks in model order
  std::vector<std::string> constant_blocks;  // computed once, at initialisation, in execution order
  std::vector<Diagnostic> diagnostics;
};

[[nodiscard]] RateAnalysis analyse_rates(const Model& model);
[[nodiscard]] std::string describe(const Rate& rate, double base_period_us);

}  // namespace duet::model
