#include "block_semantics.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <utility>

namespace duet::model {

std::string sum_signs(const ProgramBlock& block) {
  const Argument* signs = block.argument("signs");
  std::string text = signs == nullptr ? std::string{} : signs->text;
  text.erase(std::remove(text.begin(), text.end(), '|'), text.end());  // Simulink writes "|+-"
  text.resize(std::max(text.size(), block.inputs.size()), '+');
  return text;
}

std::string product_signs(const ProgramBlock& block) {
  const Argument* signs = block.argument("signs");
  std::string text = signs == nullptr ? std::string{} : signs->text;
  text.resize(std::max(text.size(), block.inputs.size()), '*');
  return text;
}

namespace {

double number(const ProgramBlock& block, const char* name, double fallback) {
  const Argument* argument = block.argument(name);
  if (argument == nullptr || argument->value.elements.empty()) return fallback;
  return argument->value.elements.front();
}

std::uint32_t steps_of(double seconds, double period_s) {
  if (!(period_s > 0) || !(seconds > 0)) return 0;
  const double steps = std::round(seconds / period_s);
  return steps >= 4294967295.0 ? 4294967295U : static_cast<std::uint32_t>(steps);
}

}  // namespace

SourceSteps source_steps(const ProgramBlock& block) {
  if (block.type() == "Step") return {steps_of(number(block, "time_s", 0), block.period_s), 0, 0};
  return {steps_of(number(block, "delay_s", 0), block.period_s), steps_of(number(block, "period_s", 0), block.period_s),
          steps_of(number(block, "width_s", 0), block.period_s)};
}

blocks::Endian endian_of(const ProgramBlock& block) {
  const Argument* endian = block.argument("endian");
  return endian != nullptr && endian->text == "big" ? blocks::Endian::big : blocks::Endian::little;
}

std::size_t unpack_offset(const ProgramBlock& block) { return static_cast<std::size_t>(number(block, "offset", 0)); }

std::optional<std::size_t> input_of(const ProgramBlock& block, std::string_view port) {
  const auto found = std::find(block.input_ports.begin(), block.input_ports.end(), port);
  if (found == block.input_ports.end()) return std::nullopt;
  return static_cast<std::size_t>(found - block.input_ports.begin());
}

std::size_t block_window(const ProgramBlock& block) {
  return static_cast<std::size_t>(std::max(1.0, number(block, "window", 1)));
}

bool anti_windup_clamping(const ProgramBlock& block) {
  const Argument* anti_windup = block.argument("anti_windup");
  return anti_windup != nullptr && anti_windup->text == "clamping";
}

ArgumentSize argument_size(const Program& program, const ProgramBlock& block, const std::string& name) {
  const Argument* argument = block.argument(name);
  if (argument == nullptr) return {};
  const Value& value =
      argument->kind == Argument::Kind::parameter ? program.parameter(*argument).value : argument->value;
  return {value.shape.empty() ? 1 : value.shape[0], value.shape.size() == 2 ? value.shape[1] : 1,
          value.elements.size()};
}

MatrixSizes matrix_sizes(const Program& program, const ProgramBlock& block) {
  const SignalType& a = program.signals[block.inputs.at(0)].type;
  const SignalType& b = program.signals[block.inputs.at(1)].type;
  MatrixSizes sizes;
  sizes.rows = a.shape.empty() ? 1 : a.shape[0];
  sizes.inner = a.shape.size() == 2 ? a.shape[1] : 1;
  sizes.columns = b.shape.size() == 2 ? b.shape[1] : 1;
  return sizes;
}

std::size_t demux_element(const std::string& port) { return std::stoul(port.substr(1)) - 1; }

std::optional<blocks::CompareOperator> parse_compare_operator(std::string_view text) {
  using blocks::CompareOperator;
  constexpr std::array<std::pair<std::string_view, CompareOperator>, 6> names{{{"<", CompareOperator::less},
                                                                               {"<=", CompareOperator::less_equal},
                                                                               {"==", CompareOperator::equal},
                                                                               {"!=", CompareOperator::not_equal},
                                                                               {">=", CompareOperator::greater_equal},
                                                                               {">", CompareOperator::greater}}};
  for (const auto& [name, op] : names) {
    if (name == text) return op;
  }
  return std::nullopt;
}

std::optional<blocks::LogicOperator> parse_logic_operator(std::string_view text) {
  using blocks::LogicOperator;
  constexpr std::array<std::pair<std::string_view, LogicOperator>, 5> names{{{"AND", LogicOperator::logical_and},
                                                                             {"OR", LogicOperator::logical_or},
                                                                             {"XOR", LogicOperator::logical_xor},
                                                                             {"NAND", LogicOperator::logical_nand},
                                                                             {"NOR", LogicOperator::logical_nor}}};
  for (const auto& [name, op] : names) {
    if (name == text) return op;
  }
  return std::nullopt;
}

blocks::Edge edge_of(const ProgramBlock& block) {
  const Argument* edge = block.argument("edge");
  const std::string text = edge == nullptr ? std::string{} : edge->text;
  if (text == "falling") return blocks::Edge::falling;
  if (text == "either") return blocks::Edge::either;
  return blocks::Edge::rising;
}

blocks::CompareOperator compare_operator(const ProgramBlock& block) {
  const Argument* op = block.argument("operator");
  return parse_compare_operator(op == nullptr ? "" : op->text).value_or(blocks::CompareOperator::equal);
}

blocks::LogicOperator logic_operator(const ProgramBlock& block) {
  const Argument* op = block.argument("operator");
  return parse_logic_operator(op == nullptr ? "" : op->text).value_or(blocks::LogicOperator::logical_and);
}

blocks::InterpolationMethod interpolation_method(const ProgramBlock& block) {
  const Argument* method = block.argument("method");
  const std::string text = method == nullptr ? std::string{} : method->text;
  if (text == "nearest") return blocks::InterpolationMethod::nearest;
  if (text == "flat") return blocks::InterpolationMethod::flat;
  if (text == "above") return blocks::InterpolationMethod::above;
  return blocks::InterpolationMethod::linear;
}

blocks::Extrapolation extrapolation_of(const ProgramBlock& block) {
  const Argument* extrapolation = block.argument("extrapolation");
  return extrapolation != nullptr && extrapolation->text == "linear" ? blocks::Extrapolation::linear
                                                                     : blocks::Extrapolation::clip;
}

Transfer transfer_of(const Program& program, const ProgramBlock& block) {
  const std::size_t writer = block.update_task;
  const std::size_t reader = block.task;
  if (writer == at_initialisation || reader == at_initialisation) return {Transfer::Kind::latest, 1};
  const Rate& from = program.tasks[writer].rate;
  const Rate& to = program.tasks[reader].rate;
  if (from.kind != Rate::Kind::periodic || to.kind != Rate::Kind::periodic) return {Transfer::Kind::latest, 1};
  if (from.multiple < to.multiple) {
    return {Transfer::Kind::fast_to_slow, static_cast<std::uint32_t>(to.multiple / from.multiple)};
  }
  return {Transfer::Kind::slow_to_fast, static_cast<std::uint32_t>(from.multiple / to.multiple)};
}

}  // namespace duet::model
