#include "matlab_functions.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "matlab_arithmetic.hpp"
#include "matlab_evaluation.hpp"

namespace duet::simulink_import {
namespace {

using Arguments = std::vector<Value>;

struct Builtin {
  std::size_t fewest_arguments;
  std::size_t most_arguments;
  std::function<Result<Value>(std::string_view name, const Arguments&)> call;
};

std::string quoted(std::string_view name) { return "'" + std::string{name} + "'"; }

Result<Value> constant(double number, MatlabClass type = MatlabClass::double_class) {
  return Value::scalar(number, type);
}

Status numeric(std::string_view name, const Arguments& arguments) {
  for (const Value& argument : arguments) {
    if (argument.is_struct) return Failure{quoted(name) + " needs numbers, not a struct"};
  }
  return done();
}

Result<Value> map_elements(const Value& argument, MatlabClass type, const std::function<double(double)>& function) {
  Value result = argument;
  result.type = type;
  for (double& x : result.elements) x = convert_element(function(x), type);
  return result;
}

// sqrt, exp, log, the trigonometric functions: defined on floating point only, as in MATLAB.
Builtin floating(std::function<double(double)> function, bool negative_is_complex = false) {
  return {
      1, 1, [function, negative_is_complex](std::string_view name, const Arguments& arguments) -> Result<Value> {
        const Value& x = arguments[0];
        if (x.type != MatlabClass::double_class && x.type != MatlabClass::single_class) {
          return Failure{quoted(name) + " needs a double or single argument, not " + std::string{class_name(x.type)}};
        }
        if (negative_is_complex && std::any_of(x.elements.begin(), x.elements.end(), [](double e) { return e < 0; })) {
          return Failure{quoted(name) + " of a negative number gives a complex result"};
        }
        return map_elements(x, x.type, function);
      }};
}

// abs, floor, ceil, round: any class; logical gives double.
Builtin keeping_class(std::function<double(double)> function) {
  return {1, 1, [function](std::string_view, const Arguments& arguments) {
            const Value& x = arguments[0];
            return map_elements(x, x.type == MatlabClass::logical ? MatlabClass::double_class : x.type, function);
          }};
}

Builtin cast(MatlabClass type) {
  return {1, 1, [type](std::string_view, const Arguments& arguments) { return convert(arguments[0], type); }};
}

// Along the columns of a matrix, along a vector (a row or a column); a 0x0 matrix gives `empty`.
Value reduce(const Value& x, MatlabClass type, double empty, const std::function<double(double, double)>& combine,
             double start) {
  if (x.rows == 0 && x.columns == 0) return Value::scalar(empty, type);
  const bool vector = x.rows == 1 || x.columns == 1;
  const std::size_t groups = vector ? 1 : x.columns;
  const std::size_t length = vector ? x.count() : x.rows;
  std::vector<double> result(groups);
  for (std::size_t g = 0; g < groups; ++g) {
    double accumulated = start;
    for (std::size_t k = 0; k < length; ++k) accumulated = combine(accumulated, vector ? x.elements[k] : x.at(k, g));
    result[g] = convert_element(accumulated, type);
  }
  return Value::matrix(1, groups, std::move(result), type);
}

// min and max skip NaN, as MATLAB does: NaN only when every element is NaN.
Builtin extremum(bool smallest) {
  const auto pick = [smallest](double a, double b) {
    if (std::isnan(a)) return b;
    if (std::isnan(b)) return a;
    return smallest ? std::min(a, b) : std::max(a, b);
  };
  return {1, 2, [pick](std::string_view name, const Arguments& arguments) -> Result<Value> {
            if (arguments.size() == 2) {
              const Result<MatlabClass> type = result_class(arguments[0], arguments[1], name);
              if (!type) return Failure{type.error()};
              return element_wise(arguments[0], arguments[1], name, type.value(), pick);
            }
            const Value& x = arguments[0];
            if (x.rows == 0 && x.columns == 0) return x;
            const MatlabClass type = x.type == MatlabClass::logical ? MatlabClass::double_class : x.type;
            return reduce(x, type, 0.0, pick, std::numeric_limits<double>::quiet_NaN());
          }};
}

Result<std::size_t> dimension(std::string_view name, double size) {
  if (std::isnan(size) || size != std::floor(size)) {
    std::ostringstream text;
    text << size;
    return Failure{quoted(name) + " needs whole sizes, not " + text.str()};
  }
  if (size > static_cast<double>(max_elements)) return Failure{quoted(name) + " would be too large"};
  return size < 0 ? std::size_t{0} : static_cast<std::size_t>(size);  // MATLAB takes negative sizes as 0
}

// zeros(n), zeros(r, c), zeros([r c]) and the like.
Result<std::pair<std::size_t, std::size_t>> matrix_size(std::string_view name, const Arguments& arguments) {
  std::vector<double> sizes;
  if (arguments.empty()) sizes = {1, 1};
  if (arguments.size() == 1) {
    const Value& x = arguments[0];
    if (x.is_scalar()) {
      sizes = {x.elements[0], x.elements[0]};
    } else if (x.rows == 1 && x.columns == 2) {
      sizes = x.elements;
    } else {
      return Failure{quoted(name) + " needs a size n or [rows columns], not " + x.size_text()};
    }
  }
  if (arguments.size() == 2) {
    for (const Value& x : arguments) {
      if (!x.is_scalar()) return Failure{quoted(name) + " needs scalar sizes, not " + x.size_text()};
      sizes.push_back(x.elements[0]);
    }
  }
  const Result<std::size_t> rows = dimension(name, sizes[0]);
  if (!rows) return Failure{rows.error()};
  const Result<std::size_t> columns = dimension(name, sizes[1]);
  if (!columns) return Failure{columns.error()};
  if (rows.value() * columns.value() > max_elements) return Failure{quoted(name) + " would be too large"};
  return std::pair{rows.value(), columns.value()};
}

Builtin filled(double fill, bool identity) {
  return {0, 2, [fill, identity](std::string_view name, const Arguments& arguments) -> Result<Value> {
            const auto size = matrix_size(name, arguments);
            if (!size) return Failure{size.error()};
            const auto [rows, columns] = size.value();
            std::vector<double> elements(rows * columns, identity ? 0.0 : fill);
            if (identity) {
              for (std::size_t k = 0; k < std::min(rows, columns); ++k) elements[k * columns + k] = 1.0;
            }
            return Value::matrix(rows, columns, std::move(elements));
          }};
}

const std::map<std::string_view, Builtin>& builtins() {
  static const std::map<std::string_view, Builtin> table{
      {"pi", {0, 0, [](std::string_view, const Arguments&) { return constant(std::numbers::pi); }}},
      {"inf", {0, 0, [](std::string_view, const Arguments&) { return constant(HUGE_VAL); }}},
      {"Inf", {0, 0, [](std::string_view, const Arguments&) { return constant(HUGE_VAL); }}},
      {"nan", {0, 0, [](std::string_view, const Arguments&) { return constant(std::nan("")); }}},
      {"NaN", {0, 0, [](std::string_view, const Arguments&) { return constant(std::nan("")); }}},
      {"eps",
       {0, 0, [](std::string_view, const Arguments&) { return constant(std::numeric_limits<double>::epsilon()); }}},
      {"true", {0, 0, [](std::string_view, const Arguments&) { return constant(1.0, MatlabClass::logical); }}},
      {"false", {0, 0, [](std::string_view, const Arguments&) { return constant(0.0, MatlabClass::logical); }}},
      {"double", cast(MatlabClass::double_class)},
      {"single", cast(MatlabClass::single_class)},
      {"int8", cast(MatlabClass::int8)},
      {"int16", cast(MatlabClass::int16)},
      {"int32", cast(MatlabClass::int32)},
      {"uint8", cast(MatlabClass::uint8)},
      {"uint16", cast(MatlabClass::uint16)},
      {"uint32", cast(MatlabClass::uint32)},
      {"logical", cast(MatlabClass::logical)},
      {"sqrt", floating([](double x) { return std::sqrt(x); }, true)},
      {"exp", floating([](double x) { return std::exp(x); })},
      {"log", floating([](double x) { return std::log(x); }, true)},
      {"sin", floating([](double x) { return std::sin(x); })},
      {"cos", floating([](double x) { return std::cos(x); })},
      {"tan", floating([](double x) { return std::tan(x); })},
      {"atan", floating([](double x) { return std::atan(x); })},
      {"atan2",
       {2, 2,
        [](std::string_view name, const Arguments& arguments) -> Result<Value> {
          for (const Value& x : arguments) {
            if (x.type != MatlabClass::double_class && x.type != MatlabClass::single_class) {
              return Failure{"'atan2' needs double or single arguments, not " + std::string{class_name(x.type)}};
            }
          }
          const Result<MatlabClass> type = result_class(arguments[0], arguments[1], name);
          if (!type) return Failure{type.error()};
          return element_wise(arguments[0], arguments[1], name, type.value(),
                              [](double y, double x) { return std::atan2(y, x); });
        }}},
      {"abs", keeping_class([](double x) { return std::abs(x); })},
      {"floor", keeping_class([](double x) { return std::floor(x); })},
      {"ceil", keeping_class([](double x) { return std::ceil(x); })},
      {"round", keeping_class([](double x) { return std::round(x); })},
      {"min", extremum(true)},
      {"max", extremum(false)},
      {"sum",
       {1, 1,
        [](std::string_view, const Arguments& arguments) {
          // The default of MATLAB's sum: single stays single, every other class sums in double.
          const Value& x = arguments[0];
          const MatlabClass type = x.type == MatlabClass::single_class ? x.type : MatlabClass::double_class;
          return Result<Value>{reduce(x, type, 0.0, std::plus<>{}, 0.0)};
        }}},
      {"numel",
       {1, 1,
        [](std::string_view, const Arguments& arguments) {
          return constant(static_cast<double>(arguments[0].count()));
        }}},
      {"zeros", filled(0.0, false)},
      {"ones", filled(1.0, false)},
      {"eye", filled(0.0, true)},
  };
  return table;
}

}  // namespace

bool is_builtin(std::string_view name) { return builtins().count(name) != 0; }

Result<Value> call_builtin(std::string_view name, const std::vector<Value>& arguments) {
  const Builtin& builtin = builtins().at(name);
  if (arguments.size() < builtin.fewest_arguments || arguments.size() > builtin.most_arguments) {
    const std::string range =
        builtin.fewest_arguments == builtin.most_arguments
            ? std::to_string(builtin.fewest_arguments)
            : std::to_string(builtin.fewest_arguments) + " to " + std::to_string(builtin.most_arguments);
    return Failure{quoted(name) + " takes " + range + " argument" + (range == "1" ? "" : "s") + ", not " +
                   std::to_string(arguments.size())};
  }
  if (name != "numel") {
    if (Status ok = numeric(name, arguments); !ok) return Failure{ok.error()};
  }
  return builtin.call(name, arguments);
}

}  // namespace duet::simulink_import
