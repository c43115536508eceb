#include "duet/simulink_import/matlab_expression.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "matlab_arithmetic.hpp"
#include "matlab_evaluation.hpp"
#include "matlab_functions.hpp"
#include "matlab_tokens.hpp"

namespace duet::simulink_import {
namespace {

// Recursive descent over MATLAB's precedence, lowest first: ':' ranges; binary + -; * / .* ./; unary + -;
// ^ .^ and the transposes (left to right, an exponent may carry its own sign: 2^-1). Evaluates as it parses.
class Parser {
 public:
  Parser(std::vector<Token> tokens, const Workspace& workspace) : tokens_(std::move(tokens)), workspace_(workspace) {}

  Value whole() {
    Value value = expression();
    while (peek().kind == Token::Kind::newline) ++next_;
    if (peek().kind != Token::Kind::end) fail(peek(), "unexpected " + describe(peek()));
    return value;
  }

 private:
  // Counts the depth of the recursion, so that no input can exhaust the stack.
  class Nesting {
   public:
    Nesting(Parser& parser, const Token& at) : parser_(parser) {
      if (++parser_.depth_ > max_nesting) {
        parser_.fail(at, "nesting deeper than " + std::to_string(max_nesting) + " levels");
      }
    }
    ~Nesting() { --parser_.depth_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

   private:
    Parser& parser_;
  };

  Value expression() {
    const Nesting nesting{*this, peek()};
    Value first = additive();
    if (!is_symbol(peek(), ":")) return first;
    const Token colon = take();
    Value second = additive();
    if (!is_symbol(peek(), ":")) return checked(colon, range(first, nullptr, second));
    take();
    const Value third = additive();
    return checked(colon, range(first, &second, third));
  }

  Value additive() {
    Value left = multiplicative();
    while ((is_symbol(peek(), "+") || is_symbol(peek(), "-")) && !splits_element()) {
      const Token op = take();
      const Value right = multiplicative();
      left = checked(op, apply_operator(op.text, left, right));
    }
    return left;
  }

  // Inside brackets `[1 -2]` is two elements and `[1 - 2]` one, as in MATLAB: a sign after a space and directly
  // before its operand starts a new element.
  bool splits_element() const {
    const Token& sign = peek();
    return in_brackets_ && sign.space_before && !tokens_[next_ + 1].space_before &&
           tokens_[next_ + 1].kind != Token::Kind::end;
  }

  Value multiplicative() {
    Value left = unary();
    while (is_symbol(peek(), "*") || is_symbol(peek(), "/") || is_symbol(peek(), ".*") || is_symbol(peek(), "./")) {
      const Token op = take();
      const Value right = unary();
      left = checked(op, apply_operator(op.text, left, right));
    }
    return left;
  }

  // A sign applies to what follows: a whole power term (-2^2 is -4), or, right after ^, the exponent alone (2^-1).
  Value unary(bool exponent = false) {
    if (is_symbol(peek(), "-") || is_symbol(peek(), "+")) {
      const Token sign = take();
      const Nesting nesting{*this, sign};
      const Value operand = unary(exponent);
      return checked(sign, sign.text == "-" ? negate(operand) : unary_plus(operand));
    }
    return exponent ? primary() : postfix();
  }

  Value postfix() {
    Value value = primary();
    while (true) {
      if (is_symbol(peek(), "'") || is_symbol(peek(), ".'")) {
        take();
        value = transpose(value);
      } else if (is_symbol(peek(), "^") || is_symbol(peek(), ".^")) {
        const Token op = take();
        const Value exponent = unary(true);
        value = checked(op, apply_operator(op.text, value, exponent));
      } else {
        return value;
      }
    }
  }

  Value primary() {
    const Token& token = peek();
    if (token.kind == Token::Kind::number) return Value::scalar(take().number);
    if (token.kind == Token::Kind::name) return named();
    if (is_symbol(token, "(")) {
      const Token open = take();
      const Nesting nesting{*this, open};
      const bool outer = in_brackets_;
      in_brackets_ = false;
      Value value = expression();
      in_brackets_ = outer;
      expect(")");
      return value;
    }
    if (is_symbol(token, "[")) return matrix();
    fail(token, "value expected, not " + describe(token));
  }

  // A variable (with fields and an index: P.gains(2)), else a built-in constant or function.
  Value named() {
    const Token name = take();
    const std::string text{name.text};
    if (text == "end") fail(name, "'end' is not supported here");
    if (const auto variable = workspace_.find(text); variable != workspace_.end()) {
      std::string path = text;
      const Value* value = &variable->second;
      while (is_symbol(peek(), ".") && tokens_[next_ + 1].kind == Token::Kind::name) {
        take();
        const Token field = take();
        if (!value->is_struct)
          fail(field, "'" + path + "' is not a struct, so it has no field '" + std::string{field.text} + "'");
        const Value* inner = value->field(field.text);
        if (inner == nullptr) fail(field, "'" + path + "' has no field '" + std::string{field.text} + "'");
        path += "." + std::string{field.text};
        value = inner;
      }
      if (opens_arguments()) return indexed(*value, path);
      return *value;
    }
    if (!is_builtin(text)) {
      if (opens_arguments()) {
        fail(name, "unresolved name '" + text + "' (no such variable, and not a function duet evaluates)");
      }
      fail(name, "unresolved name '" + text + "'");
    }
    const std::vector<Value> values = opens_arguments() ? arguments() : std::vector<Value>{};
    return checked(name, call_builtin(text, values));
  }

  // `x (2)` indexes, but inside brackets `[x (2)]` is two elements.
  bool opens_arguments() const { return is_symbol(peek(), "(") && !(in_brackets_ && peek().space_before); }

  std::vector<Value> arguments() {
    const Token open = take();
    const Nesting nesting{*this, open};
    const bool outer = in_brackets_;
    in_brackets_ = false;
    std::vector<Value> values;
    if (!is_symbol(peek(), ")")) {
      values.push_back(expression());
      while (is_symbol(peek(), ",")) {
        take();
        values.push_back(expression());
      }
    }
    in_brackets_ = outer;
    expect(")");
    return values;
  }

  // x(k) counts in MATLAB's column-major order; x(r, c) names the row and the column. 1-based.
  Value indexed(const Value& value, const std::string& path) {
    const Token& open = peek();
    const std::vector<Value> indices = arguments();
    if (indices.empty()) return value;
    if (indices.size() > 2) fail(open, "'" + path + "' has two dimensions, not " + std::to_string(indices.size()));
    std::vector<std::size_t> positions;
    for (const Value& index : indices) {
      if (!index.is_scalar()) fail(open, "an index of '" + path + "' must be a scalar, not " + index.size_text());
      const double k = index.elements[0];
      if (!(k >= 1) || k != std::floor(k) || k > 1e15) {
        fail(open, "index " + number_text(k) + " of '" + path + "' is not a positive whole number");
      }
      positions.push_back(static_cast<std::size_t>(k) - 1);
    }
    const std::size_t rows = value.is_struct ? 1 : value.rows;
    const std::size_t columns = value.is_struct ? 1 : value.columns;
    const bool linear = positions.size() == 1;
    const std::size_t row = linear ? (rows == 0 ? 0 : positions[0] % rows) : positions[0];
    const std::size_t column = linear ? (rows == 0 ? columns : positions[0] / rows) : positions[1];
    if (row >= rows || column >= columns) {
      const std::string index =
          linear ? number_text(indices[0].elements[0])
                 : "(" + number_text(indices[0].elements[0]) + "," + number_text(indices[1].elements[0]) + ")";
      fail(open, "index " + index + " is out of range for '" + path + "' (" + std::to_string(rows) + "x" +
                     std::to_string(columns) + ")");
    }
    if (value.is_struct) return value;
    return Value::scalar(value.at(row, column), value.type);
  }

  // Elements separated by ',' or spaces, rows by ';' or newlines.
  Value matrix() {
    const Token open = take();
    const Nesting nesting{*this, open};
    const bool outer = in_brackets_;
    in_brackets_ = true;
    std::vector<Value> rows;
    std::vector<Value> row;
    const auto end_row = [&] {
      rows.push_back(checked(open, concatenate(row, true)));
      row.clear();
    };
    while (!is_symbol(peek(), "]")) {
      const Token& token = peek();
      if (token.kind == Token::Kind::end) fail(token, "']' expected");
      if (is_symbol(token, ";") || token.kind == Token::Kind::newline) {
        take();
        end_row();
        continue;
      }
      if (is_symbol(token, ",")) fail(token, "value expected before ','");
      const Token& start = peek();
      row.push_back(expression());
      if (row.back().is_struct) fail(start, "a struct cannot be an element of a matrix");
      if (is_symbol(peek(), ",")) {
        take();
      } else if (!is_symbol(peek(), "]") && !is_symbol(peek(), ";") && peek().kind != Token::Kind::newline &&
                 !peek().space_before) {
        fail(peek(), "']' expected");
      }
    }
    take();
    end_row();
    in_brackets_ = outer;
    return checked(open, concatenate(rows, false));
  }

  static bool is_symbol(const Token& token, std::string_view symbol) {
    return token.kind == Token::Kind::symbol && token.text == symbol;
  }
  static std::string describe(const Token& token) {
    if (token.kind == Token::Kind::end) return "end of text";
    if (token.kind == Token::Kind::newline) return "end of line";
    return "'" + std::string{token.text} + "'";
  }
  static std::string number_text(double x) {
    std::ostringstream text;
    text << x;
    return text.str();
  }

  const Token& peek() const { return tokens_[next_]; }
  const Token& take() {
    const Token& token = tokens_[next_];
    if (token.kind != Token::Kind::end) ++next_;
    return token;
  }
  void expect(std::string_view symbol) {
    if (!is_symbol(peek(), symbol)) fail(peek(), "'" + std::string{symbol} + "' expected");
    take();
  }
  [[noreturn]] void fail(const Token& at, const std::string& problem) const {
    throw EvaluationError{at.position, problem};
  }
  Value checked(const Token& at, Result<Value> result) const {
    if (!result) fail(at, result.error());
    return std::move(result).value();
  }

  std::vector<Token> tokens_;
  std::size_t next_ = 0;
  const Workspace& workspace_;
  int depth_ = 0;
  bool in_brackets_ = false;  // directly inside [ ], where spaces and newlines separate
};

}  // namespace

Value evaluate_or_throw(std::string_view text, const Workspace& workspace) {
  return Parser{tokenize(text), workspace}.whole();
}

Result<Value> evaluate(std::string_view text, const Workspace& workspace) {
  try {
    return evaluate_or_throw(text, workspace);
  } catch (const EvaluationError& error) {
    const std::string place = error.position.line == 1 ? "column " + std::to_string(error.position.column)
                                                       : "line " + std::to_string(error.position.line) + ", column " +
                                                             std::to_string(error.position.column);
    return Failure{place + ": " + error.problem};
  }
}

}  // namespace duet::simulink_import
