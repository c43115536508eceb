#pragma once
// The tokens of a MATLAB expression (internal to the evaluator). Comments and `...` continuations are dropped here;
// newlines stay, since inside brackets they separate rows.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "matlab_evaluation.hpp"

namespace duet::simulink_import {

struct Token {
  enum class Kind { number, name, symbol, newline, end };
  Kind kind = Kind::end;
  std::string_view text;  // the symbol ("+", ".*", "'", ".'", "(", ...), the name or the number as written
  double number = 0.0;
  TextPosition position;
  bool space_before = false;  // whitespace separated it from the previous token: inside brackets that splits elements
};

// Throws EvaluationError on a character or number outside the subset.
std::vector<Token> tokenize(std::string_view text);

}  // namespace duet::simulink_import
