#pragma once
// MATLAB's arithmetic on values (internal to the evaluator): operators, implicit expansion, the classes of results,
// ranges and concatenation. Failures say the problem without a place; the parser adds the column.

#include <functional>
#include <string_view>
#include <vector>

#include "duet/simulink_import/matlab_value.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

// The class of `left op right`: an integer class wins (two different ones are refused), then single, else double.
Result<MatlabClass> result_class(const Value& left, const Value& right, std::string_view operation);

// `function` applied element by element with MATLAB's implicit expansion (a scalar, or a row against a column),
// computed in double from operands first rounded to `type`, each result rounded to `type`.
Result<Value> element_wise(const Value& left, const Value& right, std::string_view operation, MatlabClass type,
                           const std::function<double(double, double)>& function);

// The binary operators: "+", "-", ".*", "./", ".^", "*", "/", "^".
Result<Value> apply_operator(std::string_view symbol, const Value& left, const Value& right);

Result<Value> negate(const Value& operand);      // unary minus
Result<Value> unary_plus(const Value& operand);  // logical becomes double
Value transpose(const Value& operand);           // ' and .' alike: the values are real

// start:stop or start:step:stop (`step` may be null) with MATLAB's count rule.
Result<Value> range(const Value& start, const Value* step, const Value& stop);

// [a, b, ...] and [a; b; ...]: sizes must agree, empty (0x0) parts are skipped; the class is the first integer class
// present, else single if any, else logical if all are, else double.
Result<Value> concatenate(const std::vector<Value>& parts, bool horizontally);

}  // namespace duet::simulink_import
