#pragma once
// The evaluator's failures with their place in the text (internal): evaluate() turns them into messages, the .m
// script reader into FILE:LINE messages.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "duet/simulink_import/matlab_expression.hpp"

namespace duet::simulink_import {

struct TextPosition {
  std::size_t line = 1;    // 1-based, within the evaluated text
  std::size_t column = 1;  // 1-based, in bytes
};

struct EvaluationError {
  TextPosition position;
  std::string problem;
};

inline constexpr int max_nesting = 200;               // deeper parentheses, brackets or unary chains are refused
inline constexpr std::size_t max_elements = 1000000;  // a bigger matrix is refused rather than built

// Throws EvaluationError.
Value evaluate_or_throw(std::string_view text, const Workspace& workspace);

}  // namespace duet::simulink_import
