#pragma once
// Evaluates a Simulink parameter's value, the MATLAB expression text the file stores (`Kp`, `1/Iv`, `[1 1]*5e-4`,
// `P.wind.KpI`, `single(1)`), without MATLAB: the subset docs/IMPORT.md lists, with MATLAB's rules for sizes and
// classes. Anything outside the subset is refused with the column and the problem, never guessed.

#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "duet/simulink_import/matlab_value.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

using Workspace = std::map<std::string, Value, std::less<>>;  // variable name -> value

// The value of `text`, or "column 7: ')' expected" ("line 2, column 3: ..." when the text spans lines). A trailing
// `% comment` is ignored. Names are looked up in `workspace` before the built-in constants and functions, as MATLAB
// lets variables shadow them.
Result<Value> evaluate(std::string_view text, const Workspace& workspace);

}  // namespace duet::simulink_import
