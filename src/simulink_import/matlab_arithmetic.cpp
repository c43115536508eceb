#include "matlab_arithmetic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "matlab_evaluation.hpp"

namespace duet::simulink_import {
namespace {

std::string quoted(std::string_view operation) { return "'" + std::string{operation} + "'"; }

Status numeric(const Value& operand, std::string_view operation) {
  if (operand.is_struct) return Failure{"a struct cannot be an operand of " + quoted(operation)};
  return done();
}

// Implicit expansion along one dimension: equal sizes, or one of them 1.
bool expand(std::size_t left, std::size_t right, std::size_t& result) {
  if (left == right || right == 1) {
    result = left;
  } else if (left == 1) {
    result = right;
  } else {
    return false;
  }
  return true;
}

bool is_whole(double x) { return std::isfinite(x) && x == std::floor(x); }

double power(double base, double exponent) { return std::pow(base, exponent); }

Result<Value> checked_power(const Value& left, const Value& right, std::string_view symbol, MatlabClass type) {
  bool complex = false;
  auto result = element_wise(left, right, symbol, type, [&complex](double base, double exponent) {
    if (base < 0 && !is_whole(exponent) && std::isfinite(exponent)) complex = true;
    return power(base, exponent);
  });
  if (result && complex) return Failure{quoted(symbol) + " of a negative number gives a complex result"};
  return result;
}

Result<Value> matrix_product(const Value& left, const Value& right, MatlabClass type) {
  if (left.columns != right.rows) {
    return Failure{"matrix sizes " + left.size_text() + " and " + right.size_text() + " do not agree for '*'"};
  }
  if (is_integer_class(left.type) || is_integer_class(right.type)) {  // as in MATLAB
    return Failure{"'*' of matrices needs a scalar on one side when one of them is an integer"};
  }
  const double work =
      static_cast<double>(left.rows) * static_cast<double>(left.columns) * static_cast<double>(right.columns);
  if (left.rows * right.columns > max_elements || work > 1e8) {
    return Failure{"the product of " + left.size_text() + " and " + right.size_text() + " is too large"};
  }
  const Value a = convert(left, type == MatlabClass::single_class ? type : left.type).value();
  const Value b = convert(right, type == MatlabClass::single_class ? type : right.type).value();
  std::vector<double> product(left.rows * right.columns, 0.0);
  for (std::size_t r = 0; r < left.rows; ++r) {
    for (std::size_t c = 0; c < right.columns; ++c) {
      double sum = 0.0;
      for (std::size_t k = 0; k < left.columns; ++k) sum += a.at(r, k) * b.at(k, c);
      product[r * right.columns + c] = convert_element(sum, type);
    }
  }
  return Value::matrix(left.rows, right.columns, std::move(product), type);
}

}  // namespace

Result<MatlabClass> result_class(const Value& left, const Value& right, std::string_view operation) {
  const bool left_integer = is_integer_class(left.type);
  const bool right_integer = is_integer_class(right.type);
  if (left_integer && right_integer && left.type != right.type) {
    return Failure{"integers of different classes (" + std::string{class_name(left.type)} + " and " +
                   std::string{class_name(right.type)} + ") cannot be combined with " + quoted(operation)};
  }
  if (left_integer) return left.type;
  if (right_integer) return right.type;
  if (left.type == MatlabClass::single_class || right.type == MatlabClass::single_class) {
    return MatlabClass::single_class;
  }
  return MatlabClass::double_class;
}

Result<Value> element_wise(const Value& left, const Value& right, std::string_view operation, MatlabClass type,
                           const std::function<double(double, double)>& function) {
  if (Status ok = numeric(left, operation); !ok) return Failure{ok.error()};
  if (Status ok = numeric(right, operation); !ok) return Failure{ok.error()};
  std::size_t rows = 0;
  std::size_t columns = 0;
  if (!expand(left.rows, right.rows, rows) || !expand(left.columns, right.columns, columns)) {
    return Failure{"matrix sizes " + left.size_text() + " and " + right.size_text() + " do not agree for " +
                   quoted(operation)};
  }
  if (rows * columns > max_elements) return Failure{"the result of " + quoted(operation) + " is too large"};
  // Single arithmetic happens on singles: a double operand is rounded first, as MATLAB converts it.
  const auto operand = [type](double x) { return type == MatlabClass::single_class ? convert_element(x, type) : x; };
  std::vector<double> result(rows * columns);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns; ++c) {
      const double a = operand(left.at(left.rows == 1 ? 0 : r, left.columns == 1 ? 0 : c));
      const double b = operand(right.at(right.rows == 1 ? 0 : r, right.columns == 1 ? 0 : c));
      result[r * columns + c] = convert_element(function(a, b), type);
    }
  }
  return Value::matrix(rows, columns, std::move(result), type);
}

Result<Value> apply_operator(std::string_view symbol, const Value& left, const Value& right) {
  if (Status ok = numeric(left, symbol); !ok) return Failure{ok.error()};
  if (Status ok = numeric(right, symbol); !ok) return Failure{ok.error()};
  const Result<MatlabClass> type = result_class(left, right, symbol);
  if (!type) return Failure{type.error()};
  if (symbol == "+") return element_wise(left, right, symbol, type.value(), std::plus<>{});
  if (symbol == "-") return element_wise(left, right, symbol, type.value(), std::minus<>{});
  if (symbol == ".*") return element_wise(left, right, symbol, type.value(), std::multiplies<>{});
  if (symbol == "./") return element_wise(left, right, symbol, type.value(), std::divides<>{});
  if (symbol == ".^") return checked_power(left, right, symbol, type.value());
  if (symbol == "*") {
    if (left.is_scalar() || right.is_scalar()) {
      return element_wise(left, right, symbol, type.value(), std::multiplies<>{});
    }
    return matrix_product(left, right, type.value());
  }
  if (symbol == "/") {
    if (!right.is_scalar()) {
      return Failure{"'/' needs a scalar on its right, not " + right.size_text() +
                     " (matrix division is not supported)"};
    }
    return element_wise(left, right, symbol, type.value(), std::divides<>{});
  }
  if (symbol == "^") {
    if (!left.is_scalar() || !right.is_scalar()) {
      return Failure{"'^' needs scalars, not " + left.size_text() + " and " + right.size_text() +
                     " (matrix power is not supported; '.^' is element-wise)"};
    }
    return checked_power(left, right, symbol, type.value());
  }
  return Failure{"operator " + quoted(symbol) + " is not supported"};
}

Result<Value> negate(const Value& operand) {
  if (Status ok = numeric(operand, "-"); !ok) return Failure{ok.error()};
  const MatlabClass type = operand.type == MatlabClass::logical ? MatlabClass::double_class : operand.type;
  Value result = operand;
  result.type = type;
  for (double& x : result.elements) x = convert_element(-x, type);
  return result;
}

Result<Value> unary_plus(const Value& operand) {
  if (Status ok = numeric(operand, "+"); !ok) return Failure{ok.error()};
  Value result = operand;
  if (result.type == MatlabClass::logical) result.type = MatlabClass::double_class;
  return result;
}

Value transpose(const Value& operand) {
  if (operand.is_struct) return operand;
  Value result = operand;
  std::swap(result.rows, result.columns);
  for (std::size_t r = 0; r < operand.rows; ++r) {
    for (std::size_t c = 0; c < operand.columns; ++c) result.elements[c * operand.rows + r] = operand.at(r, c);
  }
  return result;
}

// The count rule of MATLAB's colon: n steps where start + n*step lands on stop within a few rounding errors, and
// the elements built from both ends so that the last one is exact.
Result<Value> range(const Value& start, const Value* step, const Value& stop) {
  for (const Value* bound : {&start, step, &stop}) {
    if (bound == nullptr) continue;
    if (Status ok = numeric(*bound, ":"); !ok) return Failure{ok.error()};
    if (!bound->is_scalar()) return Failure{"the bounds and step of ':' must be scalars, not " + bound->size_text()};
  }
  const Value one = Value::scalar(1.0);
  const Value& increment = step != nullptr ? *step : one;
  Result<MatlabClass> type = result_class(start, increment, ":");
  if (type) type = result_class(Value::scalar(0.0, type.value()), stop, ":");
  if (!type) return Failure{type.error()};
  const double a = start.elements[0];
  const double d = increment.elements[0];
  const double b = stop.elements[0];
  if (std::isnan(a) || std::isnan(d) || std::isnan(b)) return Failure{"the bounds and step of ':' must not be NaN"};
  if (d == 0 || (d > 0 && a > b) || (d < 0 && a < b)) return Value::matrix(1, 0, {}, type.value());
  const double steps = std::round((b - a) / d);
  if (!std::isfinite(steps) || steps + 1 > static_cast<double>(max_elements)) {
    return Failure{"the range has more than " + std::to_string(max_elements) + " elements"};
  }
  auto n = static_cast<std::size_t>(steps);
  const double tolerance = 2.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b));
  if (n > 0 && (d > 0 ? a + steps * d - b : b - (a + steps * d)) > tolerance) --n;
  const double reached = a + static_cast<double>(n) * d;
  const double last = std::abs(reached - b) <= tolerance ? b : reached;  // ends exactly on stop when it lands there
  std::vector<double> elements(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    const double x = 2 * k <= n ? a + static_cast<double>(k) * d : last - static_cast<double>(n - k) * d;
    elements[k] = convert_element(x, type.value());
  }
  return Value::matrix(1, n + 1, std::move(elements), type.value());
}

Result<Value> concatenate(const std::vector<Value>& parts, bool horizontally) {
  std::vector<const Value*> present;
  for (const Value& part : parts) {
    if (part.is_struct) return Failure{"a struct cannot be an element of a matrix"};
    if (part.rows != 0 || part.columns != 0) present.push_back(&part);
  }
  if (present.empty()) return Value::matrix(0, 0, {});
  const auto integer =
      std::find_if(present.begin(), present.end(), [](const Value* v) { return is_integer_class(v->type); });
  MatlabClass type = MatlabClass::double_class;
  if (integer != present.end()) {
    type = (*integer)->type;
  } else if (std::any_of(present.begin(), present.end(),
                         [](const Value* v) { return v->type == MatlabClass::single_class; })) {
    type = MatlabClass::single_class;
  } else if (std::all_of(present.begin(), present.end(),
                         [](const Value* v) { return v->type == MatlabClass::logical; })) {
    type = MatlabClass::logical;
  }
  const Value& first = *present.front();
  std::size_t total = 0;
  for (const Value* part : present) {
    if (horizontally ? part->rows != first.rows : part->columns != first.columns) {
      return Failure{std::string{horizontally ? "horizontal" : "vertical"} + " concatenation of " + first.size_text() +
                     " and " + part->size_text() + ": the " + (horizontally ? "row" : "column") + " counts differ"};
    }
    total += horizontally ? part->columns : part->rows;
  }
  const std::size_t rows = horizontally ? first.rows : total;
  const std::size_t columns = horizontally ? total : first.columns;
  if (rows * columns > max_elements)
    return Failure{"the matrix has more than " + std::to_string(max_elements) + " elements"};
  std::vector<double> elements(rows * columns);
  std::size_t offset = 0;  // the first column (horizontally) or row of the part being placed
  for (const Value* part : present) {
    for (std::size_t r = 0; r < part->rows; ++r) {
      for (std::size_t c = 0; c < part->columns; ++c) {
        const std::size_t row = horizontally ? r : offset + r;
        const std::size_t column = horizontally ? offset + c : c;
        elements[row * columns + column] = convert_element(part->at(r, c), type);
      }
    }
    offset += horizontally ? part->columns : part->rows;
  }
  return Value::matrix(rows, columns, std::move(elements), type);
}

}  // namespace duet::simulink_import
