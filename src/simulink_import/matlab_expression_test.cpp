#include "duet/simulink_import/matlab_expression.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>
#include <string>

namespace duet::simulink_import {

void PrintTo(const Value& value, std::ostream* out) {  // readable failures
  if (value.is_struct) {
    *out << "struct with " << value.fields.size() << " fields";
    return;
  }
  *out << class_name(value.type) << " " << value.size_text() << " [";
  for (double x : value.elements) *out << " " << x;
  *out << " ]";
}

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

Value value_of(std::string_view text, const Workspace& workspace = {}) {
  const Result<Value> result = evaluate(text, workspace);
  EXPECT_TRUE(result.ok()) << text << ": " << result.error();
  return result.ok() ? result.value() : Value::structure();
}

std::string error_of(std::string_view text, const Workspace& workspace = {}) {
  const Result<Value> result = evaluate(text, workspace);
  EXPECT_FALSE(result.ok()) << text << " evaluated";
  return result.ok() ? std::string{} : result.error();
}

Value row(std::vector<double> elements, MatlabClass type = MatlabClass::double_class) {
  const std::size_t columns = elements.size();
  return Value::matrix(1, columns, std::move(elements), type);
}

double single(double x) { return static_cast<double>(static_cast<float>(x)); }

TEST(MatlabExpression, Numbers) {
  EXPECT_EQ(value_of("1"), Value::scalar(1));
  EXPECT_EQ(value_of(".5"), Value::scalar(0.5));
  EXPECT_EQ(value_of("1e-3"), Value::scalar(0.001));
  EXPECT_EQ(value_of("1E3"), Value::scalar(1000));
  EXPECT_EQ(value_of("2.5e+2"), Value::scalar(250));
  EXPECT_EQ(value_of("1."), Value::scalar(1));
  EXPECT_EQ(value_of("0.050000000000000003"), Value::scalar(0.05));  // the nearest double is 0.05's
  EXPECT_EQ(value_of("1e999"), Value::scalar(infinity));             // MATLAB reads an overflow as Inf
  EXPECT_EQ(value_of("  42  "), Value::scalar(42));
}

TEST(MatlabExpression, TrailingCommentIsIgnored) {
  EXPECT_EQ(value_of("0 % 1.50e5"), Value::scalar(0));
  EXPECT_EQ(value_of("[1 2 % first row\n 3 4]"), Value::matrix(2, 2, {1, 2, 3, 4}));
  EXPECT_EQ(value_of("1 + ... continued\n 2"), Value::scalar(3));
}

TEST(MatlabExpression, Matrices) {
  EXPECT_EQ(value_of("[1 2 3]"), row({1, 2, 3}));
  EXPECT_EQ(value_of("[1,2;3,4]"), Value::matrix(2, 2, {1, 2, 3, 4}));  // row-major
  EXPECT_EQ(value_of("[1 2\n3 4]"), Value::matrix(2, 2, {1, 2, 3, 4}));
  EXPECT_EQ(value_of("[4 5 6;16 19 20;10 18 23]"), Value::matrix(3, 3, {4, 5, 6, 16, 19, 20, 10, 18, 23}));
  EXPECT_EQ(value_of("[0.050000000000000003,0]"), row({0.05, 0}));
  EXPECT_EQ(value_of("[]"), Value::matrix(0, 0, {}));
  EXPECT_EQ(value_of("[1 , 2 ,3]"), row({1, 2, 3}));
  EXPECT_EQ(value_of("[1;2]"), Value::matrix(2, 1, {1, 2}));
  EXPECT_EQ(value_of("[1 2;]"), row({1, 2}));
}

TEST(MatlabExpression, SpacesInsideBracketsSeparateElementsAsMatlabDoes) {
  EXPECT_EQ(value_of("[1 -2]"), row({1, -2}));
  EXPECT_EQ(value_of("[1 - 2]"), Value::scalar(-1));
  EXPECT_EQ(value_of("[1-2]"), Value::scalar(-1));
  EXPECT_EQ(value_of("[1 -2 + 3]"), row({1, 1}));
  EXPECT_EQ(value_of("[x (2)]", {{"x", row({7, 8})}}), row({7, 8, 2}));
  EXPECT_EQ(value_of("[x(2) 1]", {{"x", row({7, 8})}}), row({8, 1}));
  EXPECT_EQ(value_of("[(1 -2) 3]"), row({-1, 3}));  // inside parentheses spaces do not separate
}

TEST(MatlabExpression, ConcatenationOfMatrices) {
  EXPECT_EQ(value_of("[[1 2];[3 4]]"), Value::matrix(2, 2, {1, 2, 3, 4}));
  EXPECT_EQ(value_of("[[1;2] [3;4]]"), Value::matrix(2, 2, {1, 3, 2, 4}));
  EXPECT_EQ(value_of("[a, 5; 6, 7, 8]", {{"a", row({3, 4})}}), Value::matrix(2, 3, {3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(value_of("[[] 1 []]"), Value::scalar(1));
  EXPECT_EQ(value_of("[int8(1) 2.6]"), row({1, 3}, MatlabClass::int8));  // an integer class wins, rounding
  EXPECT_EQ(value_of("[true false]"), row({1, 0}, MatlabClass::logical));
  EXPECT_EQ(value_of("[true 2]"), row({1, 2}));
}

TEST(MatlabExpression, Arithmetic) {
  const Workspace workspace{{"Iv", Value::scalar(4)}, {"Ts", Value::scalar(0.01)}, {"Kp", Value::scalar(2)}};
  EXPECT_EQ(value_of("Kp", workspace), Value::scalar(2));
  EXPECT_EQ(value_of("1/Iv", workspace), Value::scalar(0.25));
  EXPECT_EQ(value_of("Ts*5", workspace), Value::scalar(0.05));
  EXPECT_EQ(value_of("[1 1 1 1]*5e-4"), row({5e-4, 5e-4, 5e-4, 5e-4}));
  EXPECT_EQ(value_of("0*pi/180"), Value::scalar(0));
  EXPECT_EQ(value_of("2+3*4"), Value::scalar(14));
  EXPECT_EQ(value_of("(2+3)*4"), Value::scalar(20));
  EXPECT_EQ(value_of("7-2-1"), Value::scalar(4));
  EXPECT_EQ(value_of("8/2/2"), Value::scalar(2));
  EXPECT_EQ(value_of("-2^2"), Value::scalar(-4));  // power binds tighter than unary minus
  EXPECT_EQ(value_of("2^-1"), Value::scalar(0.5));
  EXPECT_EQ(value_of("2^3^2"), Value::scalar(64));  // left to right
  EXPECT_EQ(value_of("2*-3"), Value::scalar(-6));
  EXPECT_EQ(value_of("--3"), Value::scalar(3));
  EXPECT_EQ(value_of("+true"), Value::scalar(1));
  EXPECT_EQ(value_of("[2 4]/2"), row({1, 2}));
  EXPECT_EQ(value_of("[1 2].*[3 4]"), row({3, 8}));
  EXPECT_EQ(value_of("[2 4]./[1 2]"), row({2, 2}));
  EXPECT_EQ(value_of("[1 2].^2"), row({1, 4}));
  EXPECT_EQ(value_of("2.^[1 2]"), row({2, 4}));
  EXPECT_EQ(value_of("1./[2 4]"), row({0.5, 0.25}));
  EXPECT_EQ(value_of("[1 2] + 1"), row({2, 3}));
  EXPECT_EQ(value_of("[1 2] + [10;20]"), Value::matrix(2, 2, {11, 12, 21, 22}));  // implicit expansion
  EXPECT_EQ(value_of("[] + 1"), Value::matrix(0, 0, {}));
  EXPECT_EQ(value_of("1/0"), Value::scalar(infinity));
}

TEST(MatlabExpression, MatrixProduct) {
  EXPECT_EQ(value_of("[1 2;3 4]*[5;6]"), Value::matrix(2, 1, {17, 39}));
  EXPECT_EQ(value_of("[1 2]*[3;4]"), Value::scalar(11));
  EXPECT_EQ(value_of("[1;2]*[3 4]"), Value::matrix(2, 2, {3, 4, 6, 8}));
  EXPECT_EQ(value_of("2*[1 2;3 4]"), Value::matrix(2, 2, {2, 4, 6, 8}));
}

TEST(MatlabExpression, Transposes) {
  EXPECT_EQ(value_of("[1 2;3 4]'"), Value::matrix(2, 2, {1, 3, 2, 4}));
  EXPECT_EQ(value_of("[1 2 3].'"), Value::matrix(3, 1, {1, 2, 3}));
  EXPECT_EQ(value_of("x'", {{"x", row({1, 2})}}), Value::matrix(2, 1, {1, 2}));
  EXPECT_EQ(value_of("[x' x']", {{"x", row({1, 2})}}), Value::matrix(2, 2, {1, 1, 2, 2}));
  EXPECT_EQ(value_of("[1 2]''"), row({1, 2}));
  EXPECT_EQ(value_of("[1 2]'*2"), Value::matrix(2, 1, {2, 4}));
}

TEST(MatlabExpression, Ranges) {
  EXPECT_EQ(value_of("1:3"), row({1, 2, 3}));
  EXPECT_EQ(value_of("1:0.5:2"), row({1, 1.5, 2}));
  EXPECT_EQ(value_of("5:-2:1"), row({5, 3, 1}));
  EXPECT_EQ(value_of("3:1"), Value::matrix(1, 0, {}));
  EXPECT_EQ(value_of("1:0:3"), Value::matrix(1, 0, {}));
  EXPECT_EQ(value_of("[0:2 9]"), row({0, 1, 2, 9}));
  EXPECT_EQ(value_of("1:2+1"), row({1, 2, 3}));  // ':' binds loosest
  // 0.3/0.1 is 2.9999999999999996 in doubles; MATLAB still makes four elements and ends exactly on 0.3.
  const Value tenths = value_of("0:0.1:0.3");
  ASSERT_EQ(tenths.columns, 4U);
  EXPECT_EQ(tenths.elements[3], 0.3);
  EXPECT_EQ(tenths.elements[1], 0.1);
  EXPECT_EQ(value_of("0:0.1:0.35").columns, 4U);
}

TEST(MatlabExpression, Constants) {
  EXPECT_EQ(value_of("pi"), Value::scalar(std::numbers::pi));
  EXPECT_EQ(value_of("inf"), Value::scalar(infinity));
  EXPECT_EQ(value_of("Inf"), Value::scalar(infinity));
  EXPECT_EQ(value_of("-inf"), Value::scalar(-infinity));
  EXPECT_TRUE(std::isnan(value_of("nan").elements[0]));
  EXPECT_TRUE(std::isnan(value_of("NaN").elements[0]));
  EXPECT_EQ(value_of("eps"), Value::scalar(std::ldexp(1.0, -52)));
  EXPECT_EQ(value_of("true"), Value::scalar(1, MatlabClass::logical));
  EXPECT_EQ(value_of("false"), Value::scalar(0, MatlabClass::logical));
  EXPECT_EQ(value_of("pi", {{"pi", Value::scalar(3)}}), Value::scalar(3));  // variables shadow built-ins
}

TEST(MatlabExpression, IntegerCastsRoundTiesAwayFromZeroAndSaturate) {
  EXPECT_EQ(value_of("int8(2.5)"), Value::scalar(3, MatlabClass::int8));
  EXPECT_EQ(value_of("int8(-2.5)"), Value::scalar(-3, MatlabClass::int8));
  EXPECT_EQ(value_of("int8(2.4)"), Value::scalar(2, MatlabClass::int8));
  EXPECT_EQ(value_of("uint8(300)"), Value::scalar(255, MatlabClass::uint8));
  EXPECT_EQ(value_of("uint8(-5)"), Value::scalar(0, MatlabClass::uint8));
  EXPECT_EQ(value_of("int8(-200)"), Value::scalar(-128, MatlabClass::int8));
  EXPECT_EQ(value_of("int16(3)"), Value::scalar(3, MatlabClass::int16));
  EXPECT_EQ(value_of("int16(nan)"), Value::scalar(0, MatlabClass::int16));
  EXPECT_EQ(value_of("int8(inf)"), Value::scalar(127, MatlabClass::int8));
  EXPECT_EQ(value_of("int32(-inf)"), Value::scalar(-2147483648.0, MatlabClass::int32));
  EXPECT_EQ(value_of("uint16(70000)"), Value::scalar(65535, MatlabClass::uint16));
  EXPECT_EQ(value_of("uint32(1e10)"), Value::scalar(4294967295.0, MatlabClass::uint32));
  EXPECT_EQ(value_of("int32([1.5 -1.5])"), row({2, -2}, MatlabClass::int32));
}

TEST(MatlabExpression, OtherCasts) {
  EXPECT_EQ(value_of("single(1)"), Value::scalar(1, MatlabClass::single_class));
  EXPECT_EQ(value_of("single(0.1)"), Value::scalar(single(0.1), MatlabClass::single_class));
  EXPECT_NE(single(0.1), 0.1);
  EXPECT_EQ(value_of("single(1e39)"), Value::scalar(infinity, MatlabClass::single_class));
  EXPECT_EQ(value_of("double(int8(3))"), Value::scalar(3));
  EXPECT_EQ(value_of("logical(5)"), Value::scalar(1, MatlabClass::logical));
  EXPECT_EQ(value_of("logical([0 -2])"), row({0, 1}, MatlabClass::logical));
}

TEST(MatlabExpression, ClassesOfArithmetic) {
  EXPECT_EQ(value_of("int16(7)/int16(2)"), Value::scalar(4, MatlabClass::int16));  // 3.5 rounds to 4
  EXPECT_EQ(value_of("int16(-7)/2"), Value::scalar(-4, MatlabClass::int16));
  EXPECT_EQ(value_of("int8(100)+100"), Value::scalar(127, MatlabClass::int8));
  EXPECT_EQ(value_of("uint8(5)-10"), Value::scalar(0, MatlabClass::uint8));
  EXPECT_EQ(value_of("2.6*int8(1)"), Value::scalar(3, MatlabClass::int8));
  EXPECT_EQ(value_of("int8(5)/0"), Value::scalar(127, MatlabClass::int8));
  EXPECT_EQ(value_of("-uint8(5)"), Value::scalar(0, MatlabClass::uint8));
  EXPECT_EQ(value_of("-int8(-128)"), Value::scalar(127, MatlabClass::int8));
  EXPECT_EQ(value_of("single(1)+1"), Value::scalar(2, MatlabClass::single_class));
  // The double operand becomes single before the product, as MATLAB converts it.
  EXPECT_EQ(value_of("single(3)*0.3"), Value::scalar(single(3 * single(0.3)), MatlabClass::single_class));
  EXPECT_NE(single(3 * single(0.3)), single(0.9));  // so the rule shows
  EXPECT_EQ(value_of("true+true"), Value::scalar(2));
  EXPECT_EQ(value_of("-true"), Value::scalar(-1));
  EXPECT_EQ(value_of("int8([1 2])*2"), row({2, 4}, MatlabClass::int8));
  EXPECT_EQ(value_of("int8(2)^2"), Value::scalar(4, MatlabClass::int8));
  EXPECT_EQ(value_of("int8(3):int8(5)"), row({3, 4, 5}, MatlabClass::int8));
}

TEST(MatlabExpression, Functions) {
  EXPECT_EQ(value_of("sqrt(16)"), Value::scalar(4));
  EXPECT_EQ(value_of("sqrt([4 9])"), row({2, 3}));
  EXPECT_EQ(value_of("exp(0)"), Value::scalar(1));
  EXPECT_EQ(value_of("log(1)"), Value::scalar(0));
  EXPECT_EQ(value_of("log(0)"), Value::scalar(-infinity));
  EXPECT_EQ(value_of("abs([-3 2])"), row({3, 2}));
  EXPECT_EQ(value_of("abs(int8(-128))"), Value::scalar(127, MatlabClass::int8));
  EXPECT_EQ(value_of("sin(0)"), Value::scalar(0));
  EXPECT_EQ(value_of("cos(0)"), Value::scalar(1));
  EXPECT_EQ(value_of("tan(0)"), Value::scalar(0));
  EXPECT_EQ(value_of("atan(1)"), Value::scalar(std::atan(1.0)));
  EXPECT_EQ(value_of("atan2(1, -1)"), Value::scalar(3 * std::numbers::pi / 4));
  EXPECT_EQ(value_of("floor(-1.5)"), Value::scalar(-2));
  EXPECT_EQ(value_of("ceil(1.2)"), Value::scalar(2));
  EXPECT_EQ(value_of("round([2.5 -2.5 0.4])"), row({3, -3, 0}));
  EXPECT_EQ(value_of("min([3 1 2])"), Value::scalar(1));
  EXPECT_EQ(value_of("max([3 1 2]')"), Value::scalar(3));
  EXPECT_EQ(value_of("min([1 2;0 5])"), row({0, 2}));  // per column
  EXPECT_EQ(value_of("max(4, [1 5])"), row({4, 5}));
  EXPECT_EQ(value_of("max([nan 1])"), Value::scalar(1));  // NaN skipped
  EXPECT_EQ(value_of("min(nan, 2)"), Value::scalar(2));
  EXPECT_EQ(value_of("sum([1 2 3])"), Value::scalar(6));
  EXPECT_EQ(value_of("sum([1 2;3 4])"), row({4, 6}));
  EXPECT_EQ(value_of("sum([])"), Value::scalar(0));
  EXPECT_EQ(value_of("sum(int8([100 100]))"), Value::scalar(200));  // integers sum in double
  EXPECT_EQ(value_of("numel([1 2;3 4])"), Value::scalar(4));
  EXPECT_EQ(value_of("zeros(2)"), Value::matrix(2, 2, {0, 0, 0, 0}));
  EXPECT_EQ(value_of("zeros(1,3)"), row({0, 0, 0}));
  EXPECT_EQ(value_of("ones([2 1])"), Value::matrix(2, 1, {1, 1}));
  EXPECT_EQ(value_of("ones(0, 3)"), Value::matrix(0, 3, {}));
  EXPECT_EQ(value_of("eye(2)"), Value::matrix(2, 2, {1, 0, 0, 1}));
  EXPECT_EQ(value_of("eye(2, 3)"), Value::matrix(2, 3, {1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(value_of("zeros"), Value::scalar(0));
}

TEST(MatlabExpression, StructFieldsAndIndexing) {
  Value wind = Value::structure();
  wind.set_field("Kp", Value::scalar(0.7));
  wind.set_field("gains", row({1, 2, 3}));
  Value parameters = Value::structure();
  parameters.set_field("wind", wind);
  const Workspace workspace{
      {"P", parameters}, {"x", row({10, 20, 30})}, {"A", Value::matrix(2, 3, {1, 2, 3, 4, 5, 6})}};
  EXPECT_EQ(value_of("P.wind.Kp", workspace), Value::scalar(0.7));
  EXPECT_EQ(value_of("2*P.wind.Kp", workspace), Value::scalar(1.4));
  EXPECT_EQ(value_of("P.wind", workspace), wind);
  EXPECT_EQ(value_of("P.wind.gains(3)", workspace), Value::scalar(3));
  EXPECT_EQ(value_of("x(2)", workspace), Value::scalar(20));
  EXPECT_EQ(value_of("A(1,3)", workspace), Value::scalar(3));
  EXPECT_EQ(value_of("A(2)", workspace), Value::scalar(4));  // linear indices count down the columns
  EXPECT_EQ(value_of("A(2,1) + x(1)", workspace), Value::scalar(14));
  EXPECT_EQ(value_of("x()", workspace), row({10, 20, 30}));
}

TEST(MatlabExpression, DeepButBoundedNesting) {
  const std::string fifty = std::string(50, '(') + "1" + std::string(50, ')');
  EXPECT_EQ(value_of(fifty), Value::scalar(1));
  EXPECT_THAT(error_of(std::string(5000, '(') + "1" + std::string(5000, ')')),
              testing::EndsWith(": nesting deeper than 200 levels"));
  EXPECT_THAT(error_of(std::string(5000, '-') + "1"), testing::EndsWith(": nesting deeper than 200 levels"));
  EXPECT_THAT(error_of(std::string(5000, '[') + "1"), testing::EndsWith(": nesting deeper than 200 levels"));
  EXPECT_THAT(error_of("2^" + std::string(5000, '-') + "1"), testing::EndsWith(": nesting deeper than 200 levels"));
  std::string long_sum = "1";
  for (int k = 0; k < 20000; ++k) long_sum += "+1";  // long, not deep: no limit
  EXPECT_EQ(value_of(long_sum), Value::scalar(20001));
}

TEST(MatlabExpression, BadInputsSayWhereAndWhat) {
  const Workspace workspace{{"x", row({10, 20, 30})}, {"P", Value::structure()}};
  EXPECT_EQ(error_of("Kp"), "column 1: unresolved name 'Kp'");
  EXPECT_EQ(error_of("2*Kp + 1"), "column 3: unresolved name 'Kp'");
  EXPECT_EQ(error_of("foo(1)"),
            "column 1: unresolved name 'foo' (no such variable, and not a function duet evaluates)");
  EXPECT_EQ(error_of("(1+2"), "column 5: ')' expected");
  EXPECT_EQ(error_of("[1 2 3;4 5 6]*[1 2 3;4 5 6]"), "column 14: matrix sizes 2x3 and 2x3 do not agree for '*'");
  EXPECT_EQ(error_of("[1 2] + [1 2 3]"), "column 7: matrix sizes 1x2 and 1x3 do not agree for '+'");
  EXPECT_EQ(error_of("int8(1) + int16(1)"),
            "column 9: integers of different classes (int8 and int16) cannot be combined with '+'");
  EXPECT_EQ(error_of("int8([1 2;3 4])*[1;1]"),
            "column 16: '*' of matrices needs a scalar on one side when one of them is an integer");
  EXPECT_EQ(error_of("[1 2]^2"),
            "column 6: '^' needs scalars, not 1x2 and 1x1 (matrix power is not supported; '.^' is element-wise)");
  EXPECT_EQ(error_of("1/[1 2]"),
            "column 2: '/' needs a scalar on its right, not 1x2 (matrix division is not supported)");
  EXPECT_EQ(error_of("x(4)", workspace), "column 2: index 4 is out of range for 'x' (1x3)");
  EXPECT_EQ(error_of("x(1,4)", workspace), "column 2: index (1,4) is out of range for 'x' (1x3)");
  EXPECT_EQ(error_of("x(0)", workspace), "column 2: index 0 of 'x' is not a positive whole number");
  EXPECT_EQ(error_of("x(1.5)", workspace), "column 2: index 1.5 of 'x' is not a positive whole number");
  EXPECT_EQ(error_of("P.wind.Ki", workspace), "column 3: 'P' has no field 'wind'");
  EXPECT_EQ(error_of("x.a", workspace), "column 3: 'x' is not a struct, so it has no field 'a'");
  EXPECT_EQ(error_of("P + 1", workspace), "column 3: a struct cannot be an operand of '+'");
  EXPECT_EQ(error_of("'abc'"), "column 1: character strings ('...') are not supported");
  EXPECT_EQ(error_of("\"abc\""), "column 1: character strings (\"...\") are not supported");
  EXPECT_EQ(error_of("0x1F"), "column 1: malformed number '0x1F'");
  EXPECT_EQ(error_of("3i"), "column 1: complex numbers ('3i') are not supported");
  EXPECT_EQ(error_of("1 +"), "column 4: value expected, not end of text");
  EXPECT_EQ(error_of(""), "column 1: value expected, not end of text");
  EXPECT_EQ(error_of("1 2"), "column 3: unexpected '2'");
  EXPECT_EQ(error_of("1;"), "column 2: unexpected ';'");
  EXPECT_EQ(error_of("[1 2"), "column 5: ']' expected");
  EXPECT_EQ(error_of("[1 2; 3]"), "column 1: vertical concatenation of 1x2 and 1x1: the column counts differ");
  EXPECT_EQ(error_of("[[1;2] 3]"), "column 1: horizontal concatenation of 2x1 and 1x1: the row counts differ");
  EXPECT_EQ(error_of("[,1]"), "column 2: value expected before ','");
  EXPECT_EQ(error_of("1 == 1"), "column 3: operator '==' is not supported");
  EXPECT_EQ(error_of("a < b"), "column 3: operator '<' is not supported");
  EXPECT_EQ(error_of("2\\4"), "column 2: operator '\\' is not supported");
  EXPECT_EQ(error_of("1 $ 2"), "column 3: unexpected character '$'");
  EXPECT_EQ(error_of("sqrt(-1)"), "column 1: 'sqrt' of a negative number gives a complex result");
  EXPECT_EQ(error_of("(-8)^(1/3)"), "column 5: '^' of a negative number gives a complex result");
  EXPECT_EQ(error_of("sqrt(int8(4))"), "column 1: 'sqrt' needs a double or single argument, not int8");
  EXPECT_EQ(error_of("sqrt(1, 2)"), "column 1: 'sqrt' takes 1 argument, not 2");
  EXPECT_EQ(error_of("pi(2)"), "column 1: 'pi' takes 0 arguments, not 1");
  EXPECT_EQ(error_of("zeros(1.5)"), "column 1: 'zeros' needs whole sizes, not 1.5");
  EXPECT_EQ(error_of("zeros(1e4)"), "column 1: 'zeros' would be too large");
  EXPECT_EQ(error_of("logical(nan)"), "column 1: NaN cannot be converted to logical");
  EXPECT_EQ(error_of("1:1e9"), "column 2: the range has more than 1000000 elements");
  EXPECT_EQ(error_of("[1 2]:3"), "column 6: the bounds and step of ':' must be scalars, not 1x2");
  EXPECT_EQ(error_of("1:nan"), "column 2: the bounds and step of ':' must not be NaN");
  EXPECT_EQ(error_of("x(end)", workspace), "column 3: 'end' is not supported here");
  EXPECT_EQ(error_of("[1 2\n3 Kp]"), "line 2, column 3: unresolved name 'Kp'");
  EXPECT_EQ(error_of("[P 1]", workspace), "column 2: a struct cannot be an element of a matrix");
}

}  // namespace
}  // namespace duet::simulink_import
