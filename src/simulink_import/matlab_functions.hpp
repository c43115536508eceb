#pragma once
// The built-in constants and functions the evaluator knows (internal): pi, inf, nan, eps, true, false, the class
// casts, and the cheap numeric functions of docs/IMPORT.md.

#include <optional>
#include <string_view>
#include <vector>

#include "duet/simulink_import/matlab_value.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

bool is_builtin(std::string_view name);

// Precondition: is_builtin(name). Failures name the function and the problem.
Result<Value> call_builtin(std::string_view name, const std::vector<Value>& arguments);

}  // namespace duet::simulink_import
