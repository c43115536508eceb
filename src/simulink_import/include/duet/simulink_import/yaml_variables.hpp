#pragma once
// Variables for a Simulink import from a YAML file, for users who keep their parameters outside MATLAB:
//   Kp: 0.5                      # a number
//   gains: [1, 2, 3]             # a row vector
//   A: [[1, 0], [0.1, 1]]        # a matrix, row by row
//   P: {wind: {Kp: 2, Ki: 0.1}}  # a struct

#include <string>

#include "duet/simulink_import/matlab_expression.hpp"
#include "duet/support/result.hpp"

namespace duet::simulink_import {

// Every value is double. Errors: "FILE:LINE: what".
Result<Workspace> read_variables_yaml(const std::string& file);

}  // namespace duet::simulink_import
