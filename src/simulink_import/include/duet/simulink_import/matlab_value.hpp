#pragma once
// A MATLAB value as a Simulink parameter evaluates to: a two-dimensional numeric matrix with its class, or a struct of
// named fields. Scalars are 1x1, `[]` is 0x0. Elements are doubles whatever the class: every class the importer meets
// (up to int32/uint32 and single) is exact in a double, and the arithmetic rounds to the class after each operation.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "duet/support/result.hpp"

namespace duet::simulink_import {

enum class MatlabClass { double_class, single_class, int8, int16, int32, uint8, uint16, uint32, logical };

std::string_view class_name(MatlabClass type);  // "double", "single", "int8", ..., "logical"
bool is_integer_class(MatlabClass type);        // int8 ... uint32

struct Field;

struct Value {
  MatlabClass type = MatlabClass::double_class;
  std::size_t rows = 1;
  std::size_t columns = 1;
  std::vector<double> elements{0.0};  // row-major: element (r, c) is elements[r * columns + c]
  bool is_struct = false;             // a struct has no elements, only fields (in the order they were first set)
  std::vector<Field> fields;

  static Value scalar(double number, MatlabClass type = MatlabClass::double_class);
  static Value matrix(std::size_t rows, std::size_t columns, std::vector<double> row_major,
                      MatlabClass type = MatlabClass::double_class);
  static Value structure();

  [[nodiscard]] std::size_t count() const { return is_struct ? 1 : elements.size(); }  // MATLAB's numel
  [[nodiscard]] bool is_scalar() const { return !is_struct && rows == 1 && columns == 1; }
  [[nodiscard]] double at(std::size_t row, std::size_t column) const { return elements[row * columns + column]; }
  [[nodiscard]] const Value* field(std::string_view name) const;  // nullptr when absent or not a struct
  [[nodiscard]] Value* field(std::string_view name);
  void set_field(const std::string& name, Value value);  // adds or replaces; makes this a struct
  [[nodiscard]] std::string size_text() const;           // "2x3"

  bool operator==(const Value& other) const;
};

struct Field {
  std::string name;
  Value value;
  bool operator==(const Field& other) const = default;
};

// MATLAB's conversion to a class, as `int8(x)` or `single(x)` do and as arithmetic does to its results: integers
// round to nearest with ties away from zero and saturate, NaN becomes 0; single rounds to the nearest float; logical
// makes every nonzero 1 and refuses NaN. A struct is refused.
Result<Value> convert(const Value& value, MatlabClass type);
double convert_element(double number, MatlabClass type);  // one element; for logical, NaN must be refused before

}  // namespace duet::simulink_import
