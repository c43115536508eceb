#include "duet/simulink_import/matlab_value.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace duet::simulink_import {

std::string_view class_name(MatlabClass type) {
  switch (type) {
    case MatlabClass::double_class: return "double";
    case MatlabClass::single_class: return "single";
    case MatlabClass::int8: return "int8";
    case MatlabClass::int16: return "int16";
    case MatlabClass::int32: return "int32";
    case MatlabClass::uint8: return "uint8";
    case MatlabClass::uint16: return "uint16";
    case MatlabClass::uint32: return "uint32";
    case MatlabClass::logical: return "logical";
  }
  return "double";
}

bool is_integer_class(MatlabClass type) {
  return type != MatlabClass::double_class && type != MatlabClass::single_class && type != MatlabClass::logical;
}

Value Value::scalar(double number, MatlabClass type) { return matrix(1, 1, {number}, type); }

Value Value::matrix(std::size_t rows, std::size_t columns, std::vector<double> row_major, MatlabClass type) {
  Value value;
  value.type = type;
  value.rows = rows;
  value.columns = columns;
  value.elements = std::move(row_major);
  return value;
}

Value Value::structure() {
  Value value;
  value.elements.clear();
  value.is_struct = true;
  return value;
}

const Value* Value::field(std::string_view name) const {
  const auto found = std::find_if(fields.begin(), fields.end(), [name](const Field& f) { return f.name == name; });
  return found == fields.end() ? nullptr : &found->value;
}

Value* Value::field(std::string_view name) {
  const auto found = std::find_if(fields.begin(), fields.end(), [name](const Field& f) { return f.name == name; });
  return found == fields.end() ? nullptr : &found->value;
}

void Value::set_field(const std::string& name, Value value) {
  if (!is_struct) *this = structure();
  const auto found = std::find_if(fields.begin(), fields.end(), [&name](const Field& f) { return f.name == name; });
  if (found != fields.end()) {
    found->value = std::move(value);
  } else {
    fields.push_back({name, std::move(value)});
  }
}

std::string Value::size_text() const { return std::to_string(rows) + "x" + std::to_string(columns); }

bool Value::operator==(const Value& other) const {
  return type == other.type && rows == other.rows && columns == other.columns && elements == other.elements &&
         is_struct == other.is_struct && fields == other.fields;
}

namespace {

struct Range {
  double low;
  double high;
};

Range integer_range(MatlabClass type) {
  switch (type) {
    case MatlabClass::int8: return {-128.0, 127.0};
    case MatlabClass::int16: return {-32768.0, 32767.0};
    case MatlabClass::int32: return {-2147483648.0, 2147483647.0};
    case MatlabClass::uint8: return {0.0, 255.0};
    case MatlabClass::uint16: return {0.0, 65535.0};
    case MatlabClass::uint32: return {0.0, 4294967295.0};
    default: return {0.0, 0.0};
  }
}

// Rounds to the nearest float without converting an out-of-range double, which C++ leaves undefined.
double to_single(double number) {
  constexpr double largest = std::numeric_limits<float>::max();
  const double overflow_threshold = std::ldexp(1.0, 128) - std::ldexp(1.0, 103);  // halfway past the largest float
  if (std::isnan(number) || std::abs(number) <= largest) return static_cast<double>(static_cast<float>(number));
  if (std::abs(number) >= overflow_threshold) return std::copysign(std::numeric_limits<double>::infinity(), number);
  return std::copysign(largest, number);
}

}  // namespace

double convert_element(double number, MatlabClass type) {
  switch (type) {
    case MatlabClass::double_class: return number;
    case MatlabClass::single_class: return to_single(number);
    case MatlabClass::logical: return number != 0.0 ? 1.0 : 0.0;
    default: {
      if (std::isnan(number)) return 0.0;
      const Range range = integer_range(type);
      return std::clamp(std::round(number), range.low, range.high);  // std::round: ties away from zero, as MATLAB
    }
  }
}

Result<Value> convert(const Value& value, MatlabClass type) {
  if (value.is_struct) return Failure{"a struct cannot be converted to " + std::string{class_name(type)}};
  if (type == MatlabClass::logical &&
      std::any_of(value.elements.begin(), value.elements.end(), [](double x) { return std::isnan(x); })) {
    return Failure{"NaN cannot be converted to logical"};
  }
  Value converted = value;
  converted.type = type;
  for (double& element : converted.elements) element = convert_element(element, type);
  return converted;
}

}  // namespace duet::simulink_import
