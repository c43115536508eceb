#pragma once
// The duet model the importer builds, and its YAML text (docs/MODELS.md): blocks with their parameters, ports and
// periods as text, each with a comment naming the Simulink block it comes from.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "duet/simulink_import/matlab_value.hpp"

namespace duet::simulink_import {

using TextPairs = std::vector<std::pair<std::string, std::string>>;  // name -> YAML value text, in order

struct DuetBlock {
  std::string name;
  std::string type;
  TextPairs parameters;
  TextPairs inputs;           // port -> signal
  TextPairs outputs;          // port -> signal
  std::string period;         // "period_us: 10000", or empty (inherited)
  std::string trigger;        // a subsystem's "{edge: rising, signal: x}" or "{interrupt: TIM2, priority: 3}", or empty
  std::string enable;         // a subsystem's enabling signal, or empty
  std::string source;         // the Simulink block it comes from: "tilt_loop/Scale/times k (Gain)"
  std::string floating_only;  // why it must compute in floating point, where integers would differ; not written
  std::vector<DuetBlock> blocks;  // a subsystem's
};

struct DuetParameter {
  std::string name;
  std::string value;  // YAML text: 2.5, [1, 2], [[1, 0], [0, 1]]
  std::string type;   // empty for double
  std::string source;
};

struct DuetModel {
  std::string name;
  std::string description;
  long long base_period_us = 0;
  std::vector<DuetParameter> parameters;
  std::vector<DuetBlock> blocks;
};

// The model file's text.
[[nodiscard]] std::string duet_model_text(const DuetModel& model);

// A number as YAML: the shortest text that reads back as the same double; .inf, -.inf, .nan.
[[nodiscard]] std::string yaml_number(double value);
// A value as YAML: a number, a list for a vector, a list of rows for a matrix.
[[nodiscard]] std::string yaml_value(const Value& value);

// A YAML scalar that reads back as `text`, quoted where YAML would read it otherwise.
[[nodiscard]] std::string yaml_string(const std::string& text);

}  // namespace duet::simulink_import
