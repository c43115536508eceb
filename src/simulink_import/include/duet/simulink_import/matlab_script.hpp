#pragma once
// Variables from a MATLAB .m script of plain assignments, the way Simulink users keep their parameters
// (`Kp = 0.5;`, `P.wind.Kp = 2*Kp;`), read without MATLAB.

#include <string>
#include <string_view>

#include "duet/simulink_import/matlab_expression.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

// Runs the assignments of `text` in order on `start`: `name = expr`, `s.a.b = expr` (builds structs), ended by `;`,
// `,` or the line's end, several on a line; `%` comments, `%{ ... %}` blocks and `...` continuations. Anything else
// (a function call as a statement, if/for, load, clear, indexed assignment) is refused: "FILE:LINE: what", and a
// problem in an expression "FILE:LINE:COLUMN: what".
Result<Workspace> read_m_script(std::string_view text, const std::string& file, Workspace start = {});

}  // namespace duet::simulink_import
